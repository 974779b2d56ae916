// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FarPointSeeds.h
/// Beyond the thesis, opt-in (ReconstructionOptions::SeedFarPoints): a later
/// run regrows what a coarser run lost. A run whose cells are too large for a
/// thin part (an ear's tip, a limb) lets the flow (4.22) shrink it away; the
/// next run, on cells half as large, starts from that surface and the energy
/// (4.29) alone does not grow it back. So the points the previous run left
/// outside its surface by more than t (seedThreshold) put balls of radius
/// SeedRadiusFactor t back into the transferred level set: phi = min(phi,
/// |x - Q| - r), the union of the inside with the balls (1.46)-(1.49) on the
/// finer grid, which then flows onto the points as any initial surface; balls
/// not attached to the surface are dropped. The points are found where each
/// storage holds phi (each rank its own) and gathered in the order of the
/// cloud, so every rank adds the same balls (Documentation/Numerics.md).

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/recon/PointClusters.h"
#include "sltk/recon/ReconstructionOptions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace sltk
{

/// The balls a run adds to the transferred level set: centres (unit-box units) and one radius.
template <int D>
struct FarPointSeeds
{
  std::vector<std::array<double, D>> Centres;
  double Radius = 0.0;

  bool empty() const { return this->Centres.empty(); }
};

/// A point seeds a ball when I[phi](Q) exceeds this: one cell of the run that
/// left it and h_P (nearer than the cloud's spacing a distance is the sampling's
/// own scatter, misfitDistance in StoppingRule.h).
inline double seedThreshold(double dx, double cloudSpacing)
{
  return std::max(dx, cloudSpacing);
}

/// The balls' radius over the threshold: the nearest seeds (I[phi](Q) just
/// above it) reach half a threshold into the surface, and a chain of seeds
/// sampled at h_P <= threshold overlaps.
constexpr double SeedRadiusFactor = 1.5;

namespace detail
{
/// Which of the points (ascending) keep their ball: those whose balls connect,
/// through overlapping balls, to one that reaches into the surface (I[phi](Q) < r).
/// A ball alone in the open (a stray point, an isolated sample of a part too thin
/// for the grids) would otherwise become a piece of its own.
template <int D>
std::vector<bool> attachedToSurface(const std::vector<PlacedPoint<D>>& points, double radius)
{
  const std::vector<Index> group = placedGroups(points, 2.0 * radius);
  const size_t n = points.size();
  std::vector<bool> rooted(n, false), kept(n);
  for (size_t j = 0; j < n; ++j)
  {
    if (points[j].Value < radius)
    {
      rooted[static_cast<size_t>(group[j])] = true;
    }
  }
  for (size_t j = 0; j < n; ++j)
  {
    kept[j] = rooted[static_cast<size_t>(group[j])];
  }
  return kept;
}
} // namespace detail

/// The seeds from the points `local` that this rank found outside by more than
/// `threshold` (seedThreshold): gathered over the ranks in the cloud's order,
/// each with a ball of SeedRadiusFactor thresholds, those not attached to the
/// surface dropped (detail::attachedToSurface). Collective.
template <int D>
FarPointSeeds<D> gatherSeeds(const std::vector<PlacedPoint<D>>& local, double threshold, const Communicator& comm)
{
  const std::vector<PlacedPoint<D>> all = gatherPlaced(local, comm);
  FarPointSeeds<D> seeds;
  seeds.Radius = SeedRadiusFactor * threshold;
  const std::vector<bool> kept = detail::attachedToSurface(all, seeds.Radius);
  for (size_t j = 0; j < all.size(); ++j)
  {
    if (kept[j])
    {
      seeds.Centres.push_back(all[j].X);
    }
  }
  return seeds;
}

/// The seeds run `run` leaves for the next, from `band` (a storage's band:
/// grid() and outsidePoints(threshold), this rank's points): none after the
/// last run, after a run that failed (`ran` false) or with SeedFarPoints off.
/// Collective.
template <int D, class Band>
FarPointSeeds<D> seedsAfterRun(const Band& band, double cloudSpacing, const ReconstructionOptions& options, int run,
  bool ran, const Communicator& comm)
{
  if (!ran || !options.SeedFarPoints || run >= options.Runs)
  {
    return {};
  }
  const double threshold = seedThreshold(band.grid().Spacing[0], cloudSpacing);
  return gatherSeeds<D>(band.outsidePoints(threshold), threshold, comm);
}

/// phi = min(phi, |x - Q| - r) at the nodes of phi's rows [firstRow, endRow)
/// along the last axis (a slab's owned rows; its ghost rows then come from
/// their owners) within r + `reach` of a seed Q: nodes farther are left alone,
/// which changes nothing once phi is cut at `reach` (1.49). The rows are
/// shared out over the threads; the result does not depend on the order.
template <int D>
void addSeedBalls(
  const FarPointSeeds<D>& seeds, double reach, Index firstRow, Index endRow, const Context& ctx, GridField<D>& phi)
{
  if (seeds.empty())
  {
    return;
  }
  const GridSpec<D>& g = phi.spec();
  const double outer = seeds.Radius + reach;
  ctx.parallelFor(
    firstRow, endRow,
    [&](Index chunkBegin, Index chunkEnd)
    {
      for (const std::array<double, D>& c : seeds.Centres)
      {
        std::array<Index, D> lo{}, hi{};
        bool empty = false;
        for (int a = 0; a < D; ++a)
        {
          const Index top = a == D - 1 ? chunkEnd - 1 : g.Dims[a] - 1;
          const Index bottom = a == D - 1 ? chunkBegin : 0;
          lo[a] = std::max<Index>(bottom, static_cast<Index>(std::ceil(g.indexCoordinate(a, c[a] - outer))));
          hi[a] = std::min<Index>(top, static_cast<Index>(std::floor(g.indexCoordinate(a, c[a] + outer))));
          empty = empty || lo[a] > hi[a];
        }
        if (empty)
        {
          continue;
        }
        forEachIndexInBox<D>(lo, hi,
          [&](const std::array<Index, D>& i)
          {
            double r2 = 0.0;
            for (int a = 0; a < D; ++a)
            {
              const double t = g.coordinate(a, i[a]) - c[a];
              r2 += t * t;
            }
            double& v = phi(i);
            v = std::min(v, std::sqrt(r2) - seeds.Radius);
          });
      }
    },
    1);
}

} // namespace sltk
