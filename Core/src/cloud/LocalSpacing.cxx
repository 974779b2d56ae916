// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/LocalSpacing.h"

#include "SampleOnOwners.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/exec/OrderStatistics.h"

#include <algorithm>
#include <memory>

namespace sltk
{

namespace
{
/// answerOnOwners()'s query of the density spacing s(Q): Q's k nearest, and how far they reach.
template <int D>
auto densityQuery(int k)
{
  return [k](const PointLocator<D>& locator, std::int64_t i, std::vector<typename PointLocator<D>::Hit>& hits)
  {
    const bool enough = locator.cloud().size() > k;
    hits.clear(); // too few points held: no neighbours, asked again on the ranks
    if (enough)
    {
      locator.nearest(locator.cloud().Points[static_cast<size_t>(i)], k, i, hits);
    }
    const double reach = enough ? hits.back().Distance : std::numeric_limits<double>::infinity();
    return OwnedAnswer{ enough ? densitySpacing<D>(reach, k) : 0.0, reach };
  };
}

} // namespace

template <int D>
Status densitySpacings(const PointLocator<D>& locator, int k, const Context& ctx, std::vector<double>& spacing,
  std::vector<std::int64_t>* neighbours)
{
  const PointCloud<D>& cloud = locator.cloud();
  const std::int64_t n = cloud.size();
  if (k < 1 || n <= k)
  {
    return Status::invalidArgument("the density spacing needs k >= 1 neighbours and more than k points");
  }
  spacing.assign(static_cast<size_t>(n), 0.0);
  if (neighbours)
  {
    neighbours->assign(static_cast<size_t>(n * k), 0);
  }
  ctx.parallelFor(0, n,
    [&](Index b, Index e)
    {
      std::vector<typename PointLocator<D>::Hit> hits;
      for (Index i = b; i < e; ++i)
      {
        locator.nearest(cloud.Points[static_cast<size_t>(i)], k, i, hits);
        spacing[static_cast<size_t>(i)] = densitySpacing<D>(hits.back().Distance, k);
        for (int j = 0; neighbours && j < k; ++j)
        {
          (*neighbours)[static_cast<size_t>(i * k + j)] = hits[static_cast<size_t>(j)].Index;
        }
      }
    });
  return Status::ok();
}

double medianOf(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle), values.end());
  return values[middle];
}

namespace
{
/// The smoothed s of a point: the median of its own s and its k neighbours'
/// (`local`: its s first, then theirs; reordered).
double smoothedSpacing(std::vector<double>& local, int k)
{
  std::nth_element(local.begin(), local.begin() + k / 2, local.end());
  return local[static_cast<size_t>(k / 2)];
}

/// rho of each smoothed s against their median over the cloud (none when 0:
/// duplicates everywhere leave no spacing to compare with, every factor 1).
void factorsOf(const std::vector<double>& smoothed, double median, std::vector<double>& factors)
{
  factors.assign(smoothed.size(), 1.0);
  if (!(median > 0.0))
  {
    return;
  }
  for (size_t i = 0; i < smoothed.size(); ++i)
  {
    factors[i] = std::clamp(smoothed[i] / median, 1.0, MaximumSparsity);
  }
}
} // namespace

template <int D>
Status sparsityFactors(const PointLocator<D>& locator, int k, const Context& ctx, std::vector<double>& factors)
{
  const PointCloud<D>& cloud = locator.cloud();
  const std::int64_t n = cloud.size();
  factors.assign(static_cast<size_t>(n), 1.0);
  if (k < 1)
  {
    return Status::invalidArgument("the sparsity factors need k >= 1 neighbours");
  }
  if (n <= k)
  {
    return Status::ok();
  }
  std::vector<double> spacing;
  std::vector<std::int64_t> neighbours;
  SLTK_RETURN_IF_ERROR(densitySpacings(locator, k, ctx, spacing, &neighbours));
  std::vector<double> smoothed(static_cast<size_t>(n));
  ctx.parallelFor(0, n,
    [&](Index b, Index e)
    {
      std::vector<double> local(static_cast<size_t>(k + 1));
      for (Index i = b; i < e; ++i)
      {
        local[0] = spacing[static_cast<size_t>(i)];
        for (int j = 0; j < k; ++j)
        {
          local[static_cast<size_t>(j + 1)] = spacing[static_cast<size_t>(neighbours[static_cast<size_t>(i * k + j)])];
        }
        smoothed[static_cast<size_t>(i)] = smoothedSpacing(local, k);
      }
    });
  factorsOf(smoothed, medianOf(smoothed), factors);
  return Status::ok();
}

template <int D>
Status densitySpacingsOnRanks(const OwnedPoints<D>& points, int k, const Communicator& comm, const Context& ctx,
  std::vector<std::int64_t>& own, std::vector<double>& spacing, std::int64_t& remote,
  const PointLocator<D>* heldLocator)
{
  own.clear();
  spacing.clear();
  remote = 0;
  if (k < 1 || comm.allReduce(points.Owned, ReduceOp::Sum) <= k)
  {
    return Status::invalidArgument("the density spacing needs k >= 1 neighbours and a cloud of more than k points");
  }
  for (size_t j = 0; j < points.Mine.size(); ++j)
  {
    if (points.Mine[j])
    {
      own.push_back(static_cast<std::int64_t>(j));
    }
  }
  // Each owned point's k nearest, exactly as on one rank (answerOnOwners).
  return answerOnOwners(points, own, k, comm, ctx, densityQuery<D>(k), spacing, remote,
    static_cast<std::vector<NeighbourCandidate<D>>*>(nullptr), heldLocator);
}

template <int D>
Status sparsityFactorsOnRanks(const OwnedPoints<D>& points, int k, const Communicator& comm, const Context& ctx,
  std::vector<double>& factors, std::int64_t* remote, std::int64_t batch)
{
  factors.assign(static_cast<size_t>(points.held()), 1.0);
  if (remote)
  {
    *remote = 0;
  }
  if (k < 1 || batch < 1)
  {
    return Status::invalidArgument("the sparsity factors need k >= 1 neighbours and batches of at least a point");
  }
  const std::int64_t n = comm.allReduce(points.Owned, ReduceOp::Sum);
  if (n <= k)
  {
    return Status::ok();
  }
  // One locator on the held points for the spacings and every batch below.
  const std::unique_ptr<const PointLocator<D>> locator =
    points.Owned > 0 ? std::make_unique<const PointLocator<D>>(points.Cloud) : nullptr;
  std::vector<std::int64_t> own;
  std::vector<double> spacing;
  std::int64_t asked = 0;
  SLTK_RETURN_IF_ERROR(densitySpacingsOnRanks(points, k, comm, ctx, own, spacing, asked, locator.get()));
  if (remote)
  {
    *remote = asked;
  }
  std::vector<double> held(static_cast<size_t>(points.held()), 0.0);
  for (size_t s = 0; s < own.size(); ++s)
  {
    held[static_cast<size_t>(own[s])] = spacing[s];
  }
  // The smoothing in batches of owned points (the same number of batches on every rank: the
  // steps are collective): a batch's k nearest found again (answerOnOwners, the same
  // neighbours), their s from their owners (valuesFromOwners), so the candidates of one batch
  // only are held.
  const auto count = static_cast<std::int64_t>(own.size());
  const std::int64_t batches = comm.allReduce((count + batch - 1) / batch, ReduceOp::Max);
  std::vector<double> smoothed(own.size());
  for (std::int64_t round = 0; round < batches; ++round)
  {
    const std::int64_t first = std::min(count, round * batch);
    const std::int64_t last = std::min(count, first + batch);
    const std::vector<std::int64_t> locals(own.begin() + first, own.begin() + last);
    std::vector<double> again;
    std::vector<NeighbourCandidate<D>> neighbours;
    std::int64_t askedAgain = 0;
    SLTK_RETURN_IF_ERROR(
      answerOnOwners(points, locals, k, comm, ctx, densityQuery<D>(k), again, askedAgain, &neighbours, locator.get()));
    std::vector<double> theirs; // the neighbours' s, from their owners
    SLTK_RETURN_IF_ERROR(valuesFromOwners(points, held, neighbours, comm, theirs));
    ctx.parallelFor(first, last,
      [&](Index b, Index e)
      {
        std::vector<double> local(static_cast<size_t>(k + 1));
        for (Index s = b; s < e; ++s)
        {
          local[0] = spacing[static_cast<size_t>(s)];
          std::copy_n(theirs.begin() + (s - first) * k, k, local.begin() + 1);
          smoothed[static_cast<size_t>(s)] = smoothedSpacing(local, k);
        }
      });
  }
  std::vector<double> owned;
  factorsOf(smoothed, kthSmallestOverRanks(smoothed, n / 2, comm), owned); // medianOf's middle
  for (size_t s = 0; s < own.size(); ++s)
  {
    factors[static_cast<size_t>(own[s])] = owned[s];
  }
  return Status::ok();
}

template Status densitySpacings(
  const PointLocator<2>&, int, const Context&, std::vector<double>&, std::vector<std::int64_t>*);
template Status densitySpacings(
  const PointLocator<3>&, int, const Context&, std::vector<double>&, std::vector<std::int64_t>*);
template Status sparsityFactors(const PointLocator<2>&, int, const Context&, std::vector<double>&);
template Status sparsityFactors(const PointLocator<3>&, int, const Context&, std::vector<double>&);
template Status densitySpacingsOnRanks(const OwnedPoints<2>&, int, const Communicator&, const Context&,
  std::vector<std::int64_t>&, std::vector<double>&, std::int64_t&, const PointLocator<2>*);
template Status densitySpacingsOnRanks(const OwnedPoints<3>&, int, const Communicator&, const Context&,
  std::vector<std::int64_t>&, std::vector<double>&, std::int64_t&, const PointLocator<3>*);
template Status sparsityFactorsOnRanks(
  const OwnedPoints<2>&, int, const Communicator&, const Context&, std::vector<double>&, std::int64_t*, std::int64_t);
template Status sparsityFactorsOnRanks(
  const OwnedPoints<3>&, int, const Communicator&, const Context&, std::vector<double>&, std::int64_t*, std::int64_t);

} // namespace sltk
