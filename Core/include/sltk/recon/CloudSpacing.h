// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudSpacing.h
/// h_P, the resolution of a cloud (thesis 4.5.2, below (4.36)): the mean
/// distance from a random 10% sample of the points to their nearest
/// neighbour in P. The sample comes from a fixed-seed generator, so h_P is
/// reproducible and identical for any number of threads.

#include "sltk/exec/Context.h"
#include "sltk/recon/PointCloud.h"

namespace sltk
{

struct CloudSpacingOptions
{
  double SampleFraction = 0.1;      ///< 10% in the thesis
  std::int64_t MinimumSample = 100; ///< small clouds: use up to this many points
  std::uint64_t Seed = 20240101;
};

/// Computes h_P; fails when the cloud has fewer than two distinct points.
/// Duplicate points (distance 0) are skipped: they carry no spacing.
template <int D>
Status cloudSpacing(const PointCloud<D>& cloud, const Context& ctx, double& spacing,
  const CloudSpacingOptions& options = {});

extern template Status cloudSpacing(const PointCloud<2>&, const Context&, double&, const CloudSpacingOptions&);
extern template Status cloudSpacing(const PointCloud<3>&, const Context&, double&, const CloudSpacingOptions&);

} // namespace sltk
