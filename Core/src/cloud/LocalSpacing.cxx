// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/LocalSpacing.h"

#include "sltk/cloud/CloudSpacing.h"

#include <algorithm>

namespace sltk
{

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
        std::nth_element(local.begin(), local.begin() + k / 2, local.end());
        smoothed[static_cast<size_t>(i)] = local[static_cast<size_t>(k / 2)];
      }
    });
  const double median = medianOf(smoothed);
  if (!(median > 0.0))
  {
    return Status::ok(); // duplicates everywhere: no spacing to compare with
  }
  for (std::int64_t i = 0; i < n; ++i)
  {
    factors[static_cast<size_t>(i)] = std::clamp(smoothed[static_cast<size_t>(i)] / median, 1.0, MaximumSparsity);
  }
  return Status::ok();
}

template Status densitySpacings(
  const PointLocator<2>&, int, const Context&, std::vector<double>&, std::vector<std::int64_t>*);
template Status densitySpacings(
  const PointLocator<3>&, int, const Context&, std::vector<double>&, std::vector<std::int64_t>*);
template Status sparsityFactors(const PointLocator<2>&, int, const Context&, std::vector<double>&);
template Status sparsityFactors(const PointLocator<3>&, int, const Context&, std::vector<double>&);

} // namespace sltk
