// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudNoise.h
/// Beyond the thesis: how noisy a cloud is at its own sampling scale, to choose
/// the interpolator at the feet (AutomaticParameters.h). Around a sample of the
/// points, a quadric (a parabola in 2D) is fitted by least squares to each
/// point's NoiseNeighbours nearest points in their principal frame; the noise is
/// the median of the fits' residuals (root mean square over the residual's
/// degrees of freedom) divided by h_P (CloudSpacing.h).
///
/// With 12 neighbours a smooth surface is a quadric to well below h_P, so the
/// residual measures the scatter about the surface, not its curvature: clean
/// scanned and CAD clouds give 0.00-0.04, the merged raw bunny scans 0.38, the
/// bunny with Gaussian noise of 0.1 and 0.25 h_P 0.11 and 0.27. With 40
/// neighbours the curvature of a sparse cloud (the teapot) reads as noise
/// (Documentation/Profile.md, "Why it loses on the merged scans").
/// The sample is every k-th point (at most NoiseSamples), so the value is the
/// same on any number of threads and ranks.

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/core/Status.h"
#include "sltk/exec/Context.h"

namespace sltk
{

constexpr int NoiseNeighbours = 12;
constexpr Index NoiseSamples = 2000;

/// The noise of the cloud of `locator` in units of `cloudSpacing` (h_P); fails
/// when the cloud has fewer than NoiseNeighbours + 1 points or h_P is not positive.
template <int D>
Status cloudNoise(const PointLocator<D>& locator, double cloudSpacing, const Context& ctx, double& noise);

/// cloudNoise() of a cloud of `total` points spread over the ranks by slabs
/// (PointOwners.h), bit for bit the value of the whole cloud on one rank: the
/// owners of the sampled points fit their quadrics among the points they hold
/// (with the nearest points of the ranks a fit's neighbours may lie on, when
/// they may lie beyond the halo), and the residuals meet in the sample's order
/// on every rank. Collective.
template <int D>
Status cloudNoiseOnRanks(const OwnedPoints<D>& points, std::int64_t total, double cloudSpacing,
  const Communicator& comm, const Context& ctx, double& noise);

extern template Status cloudNoise(const PointLocator<2>&, double, const Context&, double&);
extern template Status cloudNoise(const PointLocator<3>&, double, const Context&, double&);
extern template Status cloudNoiseOnRanks(
  const OwnedPoints<2>&, std::int64_t, double, const Communicator&, const Context&, double&);
extern template Status cloudNoiseOnRanks(
  const OwnedPoints<3>&, std::int64_t, double, const Communicator&, const Context&, double&);

} // namespace sltk
