// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/PointLocator.h"

#include "sltk/core/IndexBox.h"
#include "sltk/interp/Lanes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace sltk
{

namespace
{
/// squared[i] = min(squared[i], |p - x_i|^2) for the `count` points whose
/// coordinates are axes[a * count + i]: the ring search's arithmetic term by
/// term (no FMA: -ffp-contract=off), so the values are the per-point query's.
template <int D>
inline void smallestSquared(const double* p, const double* axes, std::int64_t count, double* squared)
{
  for (std::int64_t i = 0; i < count; ++i)
  {
    double d2 = 0.0;
    for (int a = 0; a < D; ++a)
    {
      const double d = p[a] - axes[a * count + i];
      d2 += d * d;
    }
    squared[i] = d2 < squared[i] ? d2 : squared[i];
  }
}

#if defined(SLTK_LANES_AVX2)
/// smallestSquared() in four lanes where the processor has AVX2 (the same operations a lane).
template <int D>
SLTK_LANES_AVX2_TARGET void smallestSquaredAvx2(
  const double* p, const double* axes, std::int64_t count, double* squared)
{
  smallestSquared<D>(p, axes, count, squared);
}
#endif
} // namespace

template <int D>
PointLocator<D>::PointLocator(const PointCloud<D>& cloud, double pointsPerBucket)
  : Cloud(&cloud)
  , Bounds(boundingBox(cloud))
{
  if (cloud.size() > MaximumIndexedPoints)
  {
    throw std::length_error("a point locator holds at most " + std::to_string(MaximumIndexedPoints) + " points, not " +
      std::to_string(cloud.size()) + ": spread the cloud over more ranks");
  }
  const double n = std::max<double>(1.0, static_cast<double>(cloud.size()));
  double diameter = this->Bounds.largestExtent();
  if (diameter == 0.0)
  {
    diameter = 1.0;
  }
  // Clouds sample a (D-1)-dimensional set: about n / pointsPerBucket buckets
  // of size h are hit when (diameter / h)^(D-1) ~ n / pointsPerBucket.
  this->Size = diameter / std::max(1.0, std::pow(n / pointsPerBucket, 1.0 / (D - 1)));
  std::int64_t total = 1;
  for (int a = 0; a < D; ++a)
  {
    this->Count[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(this->Bounds.extent(a) / this->Size) + 1);
    total *= this->Count[a];
  }
  // Keep the bucket table proportional to the cloud (thin or huge boxes).
  while (total > 8 * static_cast<std::int64_t>(n) + 64)
  {
    this->Size *= 1.5;
    total = 1;
    for (int a = 0; a < D; ++a)
    {
      this->Count[a] = std::max<std::int64_t>(1, static_cast<std::int64_t>(this->Bounds.extent(a) / this->Size) + 1);
      total *= this->Count[a];
    }
  }
  // A counting sort by bucket, points in increasing index within a bucket. Its
  // only storage is the table itself: Start[b] counts bucket b's points, then
  // (summed) ends it, then (each point put in place from the last one down)
  // begins it; the bucket of a point is computed again rather than kept (the
  // table has up to 8 entries a point: Documentation/Distributed.md, "Memory
  // per rank, step by step").
  const auto bucketOfPoint = [this](const std::array<double, D>& x)
  {
    std::array<std::int64_t, D> b;
    for (int a = 0; a < D; ++a)
    {
      b[a] = std::min(this->Count[a] - 1, static_cast<std::int64_t>((x[a] - this->Bounds.Min[a]) / this->Size));
    }
    return static_cast<size_t>(this->bucketOf(b));
  };
  this->Start.assign(static_cast<size_t>(total) + 1, 0);
  for (const auto& x : cloud.Points)
  {
    ++this->Start[bucketOfPoint(x)];
  }
  for (size_t b = 1; b < this->Start.size(); ++b)
  {
    this->Start[b] += this->Start[b - 1];
  }
  this->Points.resize(cloud.Points.size());
  for (size_t k = cloud.Points.size(); k-- > 0;)
  {
    this->Points[static_cast<size_t>(--this->Start[bucketOfPoint(cloud.Points[k])])] = static_cast<std::uint32_t>(k);
  }
  this->Coordinates.resize(cloud.Points.size());
  for (size_t p = 0; p < this->Points.size(); ++p)
  {
    this->Coordinates[p] = cloud.Points[static_cast<size_t>(this->Points[p])];
  }
}

template <int D>
std::int64_t PointLocator<D>::bucketOf(const std::array<std::int64_t, D>& b) const
{
  std::int64_t id = 0;
  for (int a = D - 1; a >= 0; --a)
  {
    id = id * this->Count[a] + b[a];
  }
  return id;
}

template <int D>
template <class Visit, class Reach>
void PointLocator<D>::search(const std::array<double, D>& x, std::int64_t exclude, Visit&& visit, Reach&& reach) const
{
  std::array<std::int64_t, D> centre;
  for (int a = 0; a < D; ++a)
  {
    const double s = (x[a] - this->Bounds.Min[a]) / this->Size;
    // floor(s) clamped to the buckets, compared as a double first (no library call, no overflow)
    centre[a] = !(s >= 0.0)
      ? 0
      : (s >= static_cast<double>(this->Count[a] - 1) ? this->Count[a] - 1 : static_cast<std::int64_t>(s));
  }
  std::int64_t maxRing = 0;
  for (int a = 0; a < D; ++a)
  {
    maxRing = std::max(maxRing, std::max(centre[a], this->Count[a] - 1 - centre[a]));
  }
  for (std::int64_t ring = 0; ring <= maxRing; ++ring)
  {
    // Points in buckets `ring` steps away (Chebyshev, in bucket units) are at least
    // (ring - 1) * Size from x, also when x lies outside the box and was clamped.
    if (reach() <= static_cast<double>(ring - 1) * this->Size)
    {
      break;
    }
    std::array<std::int64_t, D> lo, hi;
    for (int a = 0; a < D; ++a)
    {
      lo[a] = std::max<std::int64_t>(0, centre[a] - ring);
      hi[a] = std::min<std::int64_t>(this->Count[a] - 1, centre[a] + ring);
    }
    const auto visitBucket = [&](const std::array<std::int64_t, D>& b)
    {
      const std::int64_t id = this->bucketOf(b);
      for (size_t p = this->Start[static_cast<size_t>(id)]; p < this->Start[static_cast<size_t>(id) + 1]; ++p)
      {
        const std::int64_t k = this->Points[p];
        if (k == exclude)
        {
          continue;
        }
        double d2 = 0.0;
        for (int a = 0; a < D; ++a)
        {
          const double d = this->Coordinates[static_cast<size_t>(p)][a] - x[a];
          d2 += d * d;
        }
        visit(k, std::sqrt(d2));
      }
    };
    // The buckets of the ring's shell only (Chebyshev distance `ring` from the
    // centre's bucket), in the box's order (x fastest): a row along x whose
    // other coordinates lie inside the shell meets it at its two ends only, so
    // a ring costs O(ring^(D-1)) buckets, not O(ring^D).
    std::array<Index, D> rowsLow = lo, rowsHigh = hi;
    rowsHigh[0] = rowsLow[0]; // one visit per row along x
    forEachIndexInBox<D>(rowsLow, rowsHigh,
      [&](const std::array<Index, D>& row)
      {
        std::array<std::int64_t, D> b = row;
        bool rowOnShell = ring == 0;
        for (int a = 1; a < D; ++a)
        {
          rowOnShell = rowOnShell || b[a] == centre[a] - ring || b[a] == centre[a] + ring;
        }
        if (rowOnShell)
        {
          for (b[0] = lo[0]; b[0] <= hi[0]; ++b[0])
          {
            visitBucket(b);
          }
          return;
        }
        for (const std::int64_t end : { centre[0] - ring, centre[0] + ring })
        {
          if (end >= lo[0] && end <= hi[0])
          {
            b[0] = end;
            visitBucket(b);
          }
        }
      });
  }
}

template <int D>
typename PointLocator<D>::Hit PointLocator<D>::nearestWithin(const std::array<double, D>& x, double radius) const
{
  Hit best;
  best.Distance = radius;
  bool found = false;
  this->search(
    x, -1,
    [&](std::int64_t k, double d)
    {
      if (d < best.Distance || (d == best.Distance && (!found || k < best.Index)))
      {
        best.Distance = d;
        best.Index = k;
        found = true;
      }
    },
    [&] { return best.Distance; });
  return found ? best : Hit{};
}

template <int D>
typename PointLocator<D>::Hit PointLocator<D>::nearest(const std::array<double, D>& x, std::int64_t exclude) const
{
  Hit best;
  this->search(
    x, exclude,
    [&](std::int64_t k, double d)
    {
      if (d < best.Distance || (d == best.Distance && k < best.Index))
      {
        best.Distance = d;
        best.Index = k;
      }
    },
    [&] { return best.Index >= 0 ? best.Distance : std::numeric_limits<double>::infinity(); });
  return best;
}

template <int D>
void PointLocator<D>::nearest(const std::array<double, D>& x, int k, std::int64_t exclude, std::vector<Hit>& hits) const
{
  hits.clear();
  if (k < 1)
  {
    return;
  }
  const size_t want = static_cast<size_t>(k);
  const auto before = [](const Hit& u, const Hit& v)
  { return u.Distance < v.Distance || (u.Distance == v.Distance && u.Index < v.Index); };
  this->search(
    x, exclude,
    [&](std::int64_t q, double d)
    {
      const Hit h{ q, d };
      if (hits.size() == want && !before(h, hits.back()))
      {
        return;
      }
      hits.insert(std::upper_bound(hits.begin(), hits.end(), h, before), h); // k is small
      if (hits.size() > want)
      {
        hits.pop_back();
      }
    },
    [&] { return hits.size() == want ? hits.back().Distance : std::numeric_limits<double>::infinity(); });
}

template <int D>
void PointLocator<D>::within(
  const std::array<double, D>& x, double radius, std::int64_t exclude, std::vector<std::int64_t>& found) const
{
  found.clear();
  this->search(
    x, exclude,
    [&](std::int64_t q, double d)
    {
      if (d < radius)
      {
        found.push_back(q);
      }
    },
    [&] { return radius; });
}

template <int D>
void PointLocator<D>::nearestDistances(const std::array<double, D>* x, std::int64_t count, double* distances,
  std::vector<std::int64_t>& candidates, std::int64_t maxCandidates) const
{
  if (count <= 0)
  {
    return;
  }
  std::array<double, D> centre{};
  for (std::int64_t i = 0; i < count; ++i)
  {
    for (int a = 0; a < D; ++a)
    {
      centre[a] += x[i][a] / static_cast<double>(count);
    }
  }
  double spread = 0.0; // the farthest point from the centre
  for (std::int64_t i = 0; i < count; ++i)
  {
    double r2 = 0.0;
    for (int a = 0; a < D; ++a)
    {
      r2 += (x[i][a] - centre[a]) * (x[i][a] - centre[a]);
    }
    spread = std::max(spread, std::sqrt(r2));
  }
  const Hit first = this->nearest(centre);
  // The ball's radius with a margin for the rounding of the distances and of
  // the coordinates they subtract (within() keeps d < radius).
  double magnitude = first.Distance + 2.0 * spread;
  for (int a = 0; a < D; ++a)
  {
    magnitude += std::fabs(centre[a]);
  }
  const double radius = first.Distance + 2.0 * spread + 1e-12 * magnitude + 1e-300;
  candidates.clear();
  if (first.Index >= 0 && std::isfinite(radius))
  {
    this->within(centre, radius, -1, candidates);
  }
  if (candidates.empty() || static_cast<std::int64_t>(candidates.size()) > maxCandidates)
  {
    for (std::int64_t i = 0; i < count; ++i)
    {
      distances[i] = this->nearest(x[i]).Distance;
    }
    return;
  }
  // The smallest squared distance of each point, candidate after candidate
  // (the points' loop inside: no minimum carried across it), the points'
  // coordinates axis by axis so that the loop takes whole vectors; its square
  // root is the nearest distance.
  static thread_local std::vector<double> axes; // kept: no allocation a call once it is large enough
  axes.resize(static_cast<size_t>(D * count));
  for (std::int64_t i = 0; i < count; ++i)
  {
    distances[i] = std::numeric_limits<double>::infinity();
    for (int a = 0; a < D; ++a)
    {
      axes[static_cast<size_t>(a * count + i)] = x[i][a];
    }
  }
#if defined(SLTK_LANES_AVX2)
  const auto smallest = lanes::hasAvx2() ? smallestSquaredAvx2<D> : smallestSquared<D>;
#else
  const auto smallest = smallestSquared<D>;
#endif
  for (const std::int64_t k : candidates)
  {
    smallest(this->Cloud->Points[static_cast<size_t>(k)].data(), axes.data(), count, distances);
  }
  for (std::int64_t i = 0; i < count; ++i)
  {
    distances[i] = std::sqrt(distances[i]);
  }
}

template class PointLocator<2>;
template class PointLocator<3>;

} // namespace sltk
