// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudPoints.h"

#include "sltk/cloud/LocalSpacing.h"

#include <string>
#include <utility>
#include <vector>

namespace sltk
{

namespace
{
/// A value of the point with global index Id.
template <class Value>
struct Indexed
{
  std::int64_t Id;
  Value V;
};

/// valueOf(j) of every point this rank owns, with its global index.
template <class Value, int D, class ValueOf>
std::vector<Indexed<Value>> ownedValues(const OwnedPoints<D>& owned, ValueOf&& valueOf)
{
  std::vector<Indexed<Value>> mine;
  mine.reserve(static_cast<size_t>(owned.Owned));
  for (size_t j = 0; j < owned.Cloud.Points.size(); ++j)
  {
    if (owned.Mine[j])
    {
      mine.push_back({ owned.Ids[j], valueOf(j) });
    }
  }
  return mine;
}

/// Every rank's `mine` (ownedValues()) gathered into `out` at the global
/// indices, which must number 0 .. total - 1 once each (checked: the same
/// gather, so the same verdict, on every rank); `mine` is freed first. Collective.
template <class Value>
Status gatherByIndex(
  std::vector<Indexed<Value>>&& mine, std::int64_t total, const Communicator& comm, std::vector<Value>& out)
{
  const std::vector<Indexed<Value>> all = comm.allGatherV(mine);
  mine = {};
  out.assign(static_cast<size_t>(total), Value{});
  std::vector<bool> placed(static_cast<size_t>(total), false);
  bool whole = static_cast<std::int64_t>(all.size()) == total;
  for (const Indexed<Value>& p : all)
  {
    const bool inRange = p.Id >= 0 && p.Id < total;
    whole = whole && inRange && !placed[static_cast<size_t>(p.Id)];
    if (whole)
    {
      placed[static_cast<size_t>(p.Id)] = true;
      out[static_cast<size_t>(p.Id)] = p.V;
    }
  }
  if (!whole)
  {
    out.clear();
    return Status::invalidArgument("the ranks' points do not number the cloud's " + std::to_string(total) +
      " points once each (points to their owners)");
  }
  return Status::ok();
}
} // namespace

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
Status WholeCloud<D>::sparsity(int k, const Context& ctx, std::vector<double>& factors) const
{
  return sparsityFactors(this->locator(), k, ctx, factors);
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
  SLTK_RETURN_IF_ERROR(this->indexable());
  auto mine = ownedValues<std::array<double, D>>(this->Owned, [&](size_t j) { return this->Owned.Cloud.Points[j]; });
  this->Owned = OwnedPoints<D>(); // the whole cloud replaces the shares
  locator.reset();
  SLTK_RETURN_IF_ERROR(gatherByIndex(std::move(mine), this->Total, this->Comm, cloud.Points));
  this->HeldMax = std::max(this->HeldMax, cloud.size());
  locator = std::make_unique<const PointLocator<D>>(cloud, pointsPerBucket);
  return Status::ok();
}

template <int D>
Status OwnedCloud<D>::indexable() const
{
  if (this->Total > MaximumIndexedPoints) // the same on every rank
  {
    return Status::outOfMemory("the cleaned cloud has " + std::to_string(this->Total) + " points, more than the " +
      std::to_string(MaximumIndexedPoints) +
      " every rank holds and indexes for the runs: thin it (--thin F) or reconstruct it in parts");
  }
  return Status::ok();
}

template <int D>
Status OwnedCloud<D>::sparsity(int k, const Context& ctx, std::vector<double>& factors) const
{
  SLTK_RETURN_IF_ERROR(this->indexable()); // before a factor a point is gathered
  std::vector<double> held;                // a factor per held point, the owned ones the one-rank values
  SLTK_RETURN_IF_ERROR(sparsityFactorsOnRanks(this->Owned, k, this->Comm, ctx, held));
  return gatherByIndex(
    ownedValues<double>(this->Owned, [&](size_t j) { return held[j]; }), this->Total, this->Comm, factors);
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
