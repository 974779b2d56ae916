// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudPoints.h"

#include <string>
#include <utility>
#include <vector>

namespace sltk
{

template <int D>
WholeCloud<D>::WholeCloud(PointCloud<D>& cloud, double pointsPerBucket)
  : Cloud(cloud)
  , PointsPerBucket(pointsPerBucket)
{
}

template <int D>
const PointLocator<D>& WholeCloud<D>::locator() const
{
  if (!this->Locator)
  {
    this->Locator = std::make_unique<const PointLocator<D>>(this->Cloud, this->PointsPerBucket);
  }
  return *this->Locator;
}

template <int D>
Status WholeCloud<D>::validate() const
{
  return validateCloud(this->Cloud);
}

template <int D>
Box<D> WholeCloud<D>::box() const
{
  return boundingBox(this->Cloud);
}

template <int D>
Status WholeCloud<D>::transform(const PointMap<D>& map)
{
  this->Locator.reset();
  for (auto& p : this->Cloud.Points)
  {
    p = map(p);
  }
  return Status::ok();
}

template <int D>
Status WholeCloud<D>::removeOutliers(const OutlierOptions& options, const Context& ctx, OutlierReport& report)
{
  this->Locator.reset();
  return sltk::removeOutliers(this->Cloud, options, ctx, this->Cloud, report);
}

template <int D>
Status WholeCloud<D>::spacing(const Context& ctx, const CloudSpacingOptions& options, double& spacing) const
{
  if (this->Cloud.Points.empty()) // no locator on no point: the cloud's own refusal
  {
    return cloudSpacing(this->Cloud, ctx, spacing, options);
  }
  return cloudSpacing(this->locator(), ctx, spacing, options);
}

template <int D>
Status WholeCloud<D>::noise(double cloudSpacing, const Context& ctx, double& noise) const
{
  if (this->Cloud.Points.empty())
  {
    return Status::invalidArgument("the noise of a cloud needs points");
  }
  return cloudNoise(this->locator(), cloudSpacing, ctx, noise);
}

template <int D>
Status WholeCloud<D>::thin(double cell)
{
  this->Locator.reset();
  PointCloud<D> thinned;
  SLTK_RETURN_IF_ERROR(thinCloud(this->Cloud, cell, thinned));
  this->Cloud = std::move(thinned);
  return Status::ok();
}

template <int D>
Status WholeCloud<D>::release(
  PointCloud<D>& cloud, double pointsPerBucket, std::unique_ptr<const PointLocator<D>>& locator)
{
  if (&cloud != &this->Cloud || pointsPerBucket != this->PointsPerBucket)
  {
    this->Locator.reset();
    if (&cloud != &this->Cloud)
    {
      cloud = std::move(this->Cloud);
    }
  }
  locator = this->Locator ? std::move(this->Locator) : std::make_unique<const PointLocator<D>>(cloud, pointsPerBucket);
  return Status::ok();
}

template <int D>
OwnedCloud<D>::OwnedCloud(const Communicator& comm)
  : Comm(comm)
{
}

template <int D>
Status OwnedCloud<D>::own(const PointCloud<D>& share, std::int64_t firstId)
{
  this->Total = this->Comm.allReduce(share.size(), ReduceOp::Sum);
  SLTK_RETURN_IF_ERROR(sendToOwners(share, firstId, balancedCuts(share, this->Comm), 0.0, this->Comm, this->Owned));
  this->HeldMax = std::max(this->HeldMax, this->Owned.held());
  return Status::ok();
}

template <int D>
Status OwnedCloud<D>::reown()
{
  PointCloud<D> mine;
  std::vector<std::int64_t> ids;
  mine.Points.reserve(static_cast<size_t>(this->Owned.Owned));
  ids.reserve(static_cast<size_t>(this->Owned.Owned));
  for (size_t j = 0; j < this->Owned.Cloud.Points.size(); ++j)
  {
    if (this->Owned.Mine[j])
    {
      mine.Points.push_back(this->Owned.Cloud.Points[j]);
      ids.push_back(this->Owned.Ids[j]);
    }
  }
  const double halo = this->Owned.Halo;
  this->Owned = OwnedPoints<D>(); // in `mine` now
  const SlabCuts cuts = balancedCuts(mine, this->Comm);
  SLTK_RETURN_IF_ERROR(sendToOwners<D>(mine.Points, ids, cuts, halo, this->Comm, this->Owned));
  this->HeldMax = std::max(this->HeldMax, this->Owned.held());
  return Status::ok();
}

template <int D>
Status OwnedCloud<D>::validate() const
{
  return validateOwnedPoints(this->Owned.Cloud, this->Owned.Ids, this->Owned.Mine, this->Comm);
}

template <int D>
Box<D> OwnedCloud<D>::box() const
{
  return boundingBoxOverRanks(this->Owned.Cloud, this->Comm);
}

template <int D>
Status OwnedCloud<D>::transform(const PointMap<D>& map)
{
  for (auto& p : this->Owned.Cloud.Points)
  {
    p = map(p);
  }
  return this->reown();
}

template <int D>
Status OwnedCloud<D>::removeOutliers(const OutlierOptions& options, const Context& ctx, OutlierReport& report)
{
  SLTK_RETURN_IF_ERROR(removeOutliersOnRanks(this->Owned, this->Total, options, this->Comm, ctx, report));
  this->HeldMax = std::max(this->HeldMax, this->Owned.held());
  return Status::ok();
}

template <int D>
Status OwnedCloud<D>::spacing(const Context& ctx, const CloudSpacingOptions& options, double& spacing) const
{
  return cloudSpacingOnRanks(this->Owned, this->Total, this->Comm, ctx, spacing, options);
}

template <int D>
Status OwnedCloud<D>::noise(double cloudSpacing, const Context& ctx, double& noise) const
{
  return cloudNoiseOnRanks(this->Owned, this->Total, cloudSpacing, this->Comm, ctx, noise);
}

template <int D>
Status OwnedCloud<D>::thin(double cell)
{
  SLTK_RETURN_IF_ERROR(thinOnRanks(this->Owned, cell, this->Comm, this->Total));
  this->HeldMax = std::max(this->HeldMax, this->Owned.held());
  return Status::ok();
}

template <int D>
Status OwnedCloud<D>::release(
  PointCloud<D>& cloud, double pointsPerBucket, std::unique_ptr<const PointLocator<D>>& locator)
{
  if (this->Total > MaximumIndexedPoints) // the same on every rank
  {
    return Status::outOfMemory("the cleaned cloud has " + std::to_string(this->Total) + " points, more than the " +
      std::to_string(MaximumIndexedPoints) +
      " every rank holds and indexes for the runs: thin it (--thin F) or reconstruct it in parts");
  }
  struct Placed
  {
    std::int64_t Id;
    std::array<double, D> X;
  };
  std::vector<Placed> mine;
  mine.reserve(static_cast<size_t>(this->Owned.Owned));
  for (size_t j = 0; j < this->Owned.Cloud.Points.size(); ++j)
  {
    if (this->Owned.Mine[j])
    {
      mine.push_back({ this->Owned.Ids[j], this->Owned.Cloud.Points[j] });
    }
  }
  this->Owned = OwnedPoints<D>(); // the whole cloud replaces the shares
  const std::vector<Placed> all = this->Comm.allGatherV(mine);
  mine = {};
  locator.reset();
  cloud.Points.assign(static_cast<size_t>(this->Total), std::array<double, D>{});
  std::vector<bool> placed(static_cast<size_t>(this->Total), false);
  bool whole = static_cast<std::int64_t>(all.size()) == this->Total;
  for (const Placed& p : all)
  {
    const bool inRange = p.Id >= 0 && p.Id < this->Total;
    whole = whole && inRange && !placed[static_cast<size_t>(p.Id)];
    if (whole)
    {
      placed[static_cast<size_t>(p.Id)] = true;
      cloud.Points[static_cast<size_t>(p.Id)] = p.X;
    }
  }
  if (!whole) // the same gather on every rank: every rank fails alike
  {
    cloud.Points.clear();
    return Status::invalidArgument("the ranks' points do not number the cloud's " + std::to_string(this->Total) +
      " points once each (points to their owners)");
  }
  this->HeldMax = std::max(this->HeldMax, cloud.size());
  locator = std::make_unique<const PointLocator<D>>(cloud, pointsPerBucket);
  return Status::ok();
}

template <int D>
std::int64_t OwnedCloud<D>::heldMax() const
{
  return this->Comm.allReduce(this->HeldMax, ReduceOp::Max);
}

template class WholeCloud<2>;
template class WholeCloud<3>;
template class OwnedCloud<2>;
template class OwnedCloud<3>;

} // namespace sltk
