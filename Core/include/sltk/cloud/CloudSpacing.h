// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudSpacing.h
/// h_P, the resolution of a cloud (thesis 4.5.2, below (4.36)): the mean
/// distance from a random 10% sample of the points to their nearest
/// neighbour in P. The sample comes from a fixed-seed generator, so h_P is
/// reproducible and identical for any number of threads.
///
/// Beyond the thesis, the same sample gives a density spacing for clouds
/// merged from overlapping scans, where a point's nearest neighbour is often
/// a point of another scan at a tiny distance and (4.36) says little about the
/// sampling: with r_k the distance to the k-th neighbour, the surface density
/// is rho ~ k / (pi r_k^2) in 3D (k / (2 r_k) along a curve in 2D), and the
/// spacing 1 / sqrt(rho) = r_k sqrt(pi / k) (2D: 2 r_k / k). On an evenly
/// sampled surface both estimates agree within about 10%; on m overlapping
/// scans the density spacing shrinks only by sqrt(m).

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"

#include <cmath>

namespace sltk
{

struct CloudSpacingOptions
{
  double SampleFraction = 0.1;      ///< 10% in the thesis
  std::int64_t MinimumSample = 100; ///< small clouds: use up to this many points
  std::uint64_t Seed = 20240101;
  int DensityNeighbours = 0; ///< 0: h_P (4.36); k > 0: the density spacing at the k-th neighbour
};

/// The density spacing 1 / sqrt(rho) from r_k, the distance to the k-th
/// neighbour: rho = k / (pi r_k^2) on a surface (D = 3), k / (2 r_k) on a curve.
template <int D>
double densitySpacing(double kthDistance, int k)
{
  return kthDistance * (D == 3 ? std::sqrt(3.14159265358979323846 / k) : 2.0 / k);
}

/// Computes h_P (or the density spacing); fails when the cloud has fewer than
/// two distinct points (density spacing: fewer than k + 1 points).
/// Duplicate points (distance 0) are skipped: they carry no spacing.
template <int D>
Status cloudSpacing(
  const PointCloud<D>& cloud, const Context& ctx, double& spacing, const CloudSpacingOptions& options = {});

/// The same with the caller's locator (on the cloud it measures): one bucketing per cloud.
template <int D>
Status cloudSpacing(
  const PointLocator<D>& locator, const Context& ctx, double& spacing, const CloudSpacingOptions& options = {});

/// cloudSpacing() of a cloud of `total` points spread over the ranks by
/// slabs (PointOwners.h), bit for bit the value of the whole cloud on one rank:
/// every rank draws the same sample of global indices, the owners of the
/// sampled points find their neighbours among the points they hold, and the
/// distances are added in the sample's order. A neighbour farther than the
/// halo may have a closer rival on another rank: then the ranks within its
/// distance send their nearest points (`remote`, optional: the samples so
/// answered). Collective; fails on every rank alike.
template <int D>
Status cloudSpacingOnRanks(const OwnedPoints<D>& points, std::int64_t total, const Communicator& comm,
  const Context& ctx, double& spacing, const CloudSpacingOptions& options = {}, std::int64_t* remote = nullptr);

extern template Status cloudSpacing(const PointCloud<2>&, const Context&, double&, const CloudSpacingOptions&);
extern template Status cloudSpacing(const PointCloud<3>&, const Context&, double&, const CloudSpacingOptions&);
extern template Status cloudSpacing(const PointLocator<2>&, const Context&, double&, const CloudSpacingOptions&);
extern template Status cloudSpacing(const PointLocator<3>&, const Context&, double&, const CloudSpacingOptions&);
extern template Status cloudSpacingOnRanks(const OwnedPoints<2>&, std::int64_t, const Communicator&, const Context&,
  double&, const CloudSpacingOptions&, std::int64_t*);
extern template Status cloudSpacingOnRanks(const OwnedPoints<3>&, std::int64_t, const Communicator&, const Context&,
  double&, const CloudSpacingOptions&, std::int64_t*);

} // namespace sltk
