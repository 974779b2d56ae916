// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudThinning.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sltk
{

template <int D>
Status thinCloud(const PointCloud<D>& cloud, double cell, PointCloud<D>& thinned)
{
  if (!(cell > 0.0) || !std::isfinite(cell))
  {
    return Status::invalidArgument("the thinning cell must be positive and finite");
  }
  if (cloud.Points.empty())
  {
    thinned.Points.clear();
    return Status::ok();
  }
  const Box<D> box = boundingBox(cloud);
  std::array<std::int64_t, D> count{};
  double total = 1.0;
  for (int a = 0; a < D; ++a)
  {
    const double c = std::floor(box.extent(a) / cell) + 1.0;
    total *= c;
    count[a] = static_cast<std::int64_t>(std::min(c, 4e18));
  }
  if (!(total < 4e18))
  {
    return Status::invalidArgument("the thinning cell is too small for the cloud's extent: use a larger one");
  }
  // (cell number, point index) sorted: each cell's points in their input order.
  std::vector<std::pair<std::int64_t, std::int64_t>> keys(cloud.Points.size());
  for (size_t k = 0; k < cloud.Points.size(); ++k)
  {
    std::int64_t id = 0;
    for (int a = D - 1; a >= 0; --a)
    {
      const auto i = static_cast<std::int64_t>(std::floor((cloud.Points[k][a] - box.Min[a]) / cell));
      id = id * count[a] + std::min(count[a] - 1, std::max<std::int64_t>(0, i));
    }
    keys[k] = { id, static_cast<std::int64_t>(k) };
  }
  std::sort(keys.begin(), keys.end());
  PointCloud<D> out;
  for (size_t b = 0; b < keys.size();)
  {
    size_t e = b;
    std::array<double, D> sum{};
    for (; e < keys.size() && keys[e].first == keys[b].first; ++e)
    {
      for (int a = 0; a < D; ++a)
      {
        sum[a] += cloud.Points[static_cast<size_t>(keys[e].second)][a];
      }
    }
    for (int a = 0; a < D; ++a)
    {
      sum[a] /= static_cast<double>(e - b);
    }
    out.Points.push_back(sum);
    b = e;
  }
  thinned = std::move(out);
  return Status::ok();
}

template Status thinCloud(const PointCloud<2>&, double, PointCloud<2>&);
template Status thinCloud(const PointCloud<3>&, double, PointCloud<3>&);

} // namespace sltk
