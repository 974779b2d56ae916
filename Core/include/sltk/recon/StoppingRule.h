// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file StoppingRule.h
/// When a run of Algorithm 1 stops (thesis 4.5.1), shared by the uniform and
/// the tiled reconstructions: the rule (4.33) and the far-point fraction of
/// ReconstructionOptions::FollowFarPoints.

#include <algorithm>
#include <cmath>
#include <vector>

namespace sltk
{

/// A point is far from the surface beyond one cell of run 1 (C_dx h_P, at least h_P); the last
/// run warns (and reconstruct() starts finer, when C_dx is automatic) when more
/// than FarPointWarning of the points are. Measured after the last run with the
/// automatic parameters: the sparse npm bunny (1,839 points, C_dx = 1), whose
/// ears (one spacing thick) collapse in run 1: 2.7%; the Stanford bunny 0.03%,
/// the merged scans 0.8% at one h_P but C_dx = 3 there; kitten, frog, fandisk,
/// teapot: at most 0.4% at one h_P.
constexpr double FarPointWarning = 0.01;
/// A result fits its cloud unless more than FitShare of the points lie more than two of
/// its finest cells, and more than h_P, from its surface (RunRecord::MisfitPoints,
/// misfitDistance): then it says so (ReconstructionResult::FitsCloud, a warning; the
/// CLI's exit status 3). Why h_P too: at C_dx = 1 two finest cells are h_P / 2, and
/// the smooth surface through a sampled crease misses that by more (the fandisk: 6.9%
/// of its points beyond two cells, 0.17% beyond h_P; the teapot 12.8% and 0.6%).
constexpr double FitShare = 0.05;
/// A result fits its cloud only if it has no more pieces (InsideComponents.h) than the cloud
/// has connected components when points closer than PieceLinkFactor times their local
/// spacing, and never less than PieceLinkFactor h_P, are linked (cloudComponents,
/// PointClusters.h; Documentation/Numerics.md, "Pieces against the cloud's components").
/// Measured: the animal model 1 (its 3 h_P thick horns broke into extra pieces), two
/// spheres 0.3 r apart 2, knot2 (a link) 2, kitten, frog, fandisk, the teapot, the CAD-like
/// part3_cad 1 (at 4 h_P alone: the teapot 3, part3_cad 390). A shorter link splits a
/// sparsely sampled part into several components (the check then misses its broken parts); a
/// longer one joins separate parts (two spheres' gap) and flags their correct result.
constexpr double PieceLinkFactor = 4.0;
/// A point the surface of a run misses lies beyond two of the run's cells and beyond h_P:
/// nearer than the cloud's spacing a distance is the sampling's own uncertainty (FitShare).
inline double misfitDistance(double dx, double cloudSpacing)
{
  return std::max(2.0 * dx, cloudSpacing);
}

/// The misfit's threshold (misfitDistance) stays below gamma: at C_dx <= 1 two
/// finest cells and h_P reach gamma, and a point beyond the band would never count.
constexpr double FarBandShare = 0.999;

/// Beyond this from a run's zero level set (cells dx, band half-width gammaFactor dx)
/// a point is missed (RunRecord::MisfitPoints).
inline double misfitThreshold(double dx, double cloudSpacing, double gammaFactor)
{
  return std::min(misfitDistance(dx, cloudSpacing), FarBandShare * gammaFactor * dx);
}

/// ReconstructionOptions::FollowFarPoints: the relative fall of the far-point
/// fraction over one energy window that keeps a stalled run going.
constexpr double FarPointProgress = 0.1;

/// The stopping rule (4.33): Delta_E^n = |ebar_{n-1} - ebar_n| / ebar_n with the
/// mean ebar_n of the last k = min(n, window) energies E_2.
inline bool energyStalled(const std::vector<double>& energies, int window, double tolerance)
{
  const int n = static_cast<int>(energies.size());
  if (n < 2)
  {
    return false;
  }
  const int k = std::min(n - 1, window);
  double now = 0.0, before = 0.0;
  for (int j = 0; j < k; ++j)
  {
    now += energies[static_cast<size_t>(n - 1 - j)];
    before += energies[static_cast<size_t>(n - 2 - j)];
  }
  now /= k;
  before /= k;
  return now > 0.0 && std::fabs(before - now) / now < tolerance;
}

/// Whether a run that (4.33) would stop goes on (FollowFarPoints): while more
/// than FarPointWarning of the points are far and that fraction fell by
/// FarPointProgress since the last check (`checked`, negative before the first).
inline bool stillApproaching(double fraction, double checked)
{
  return fraction > FarPointWarning && (checked < 0.0 || fraction <= (1.0 - FarPointProgress) * checked);
}

} // namespace sltk
