// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file AutomaticParameters.h
/// Beyond the thesis: the parameters a user leaves at 0 ("automatic") are
/// chosen from the cloud by the reconstruction plan (ReconstructionPlan.h), and
/// the choices are logged with their reasons (Documentation/Numerics.md,
/// "Automatic parameters"). Given explicitly, every value is used as given, so
/// the thesis's tables are reproduced with the thesis's parameters.
///
///  - C_dx (4.36): 1, the thesis's default, unless the finest grid would not fit
///    the memory budget (AutomaticMemoryBudget unless one is given); then the
///    smallest C_dx that fits. Split over ranks, the same C_dx while the windows
///    of the ranks on each machine fit its memory (or the budget given), else
///    the smallest whose windows fit (Documentation/Distributed.md).
///  - Thinning: a cloud denser than the finest grid (its density spacing below
///    the finest dx) is thinned with a cell of AutomaticThinningFactor density
///    spacings (CloudThinning.h); the grids then follow from its h_P.
///  - K_P (4.4.4): the initial surface d = K_P h_P must enclose the object. Where
///    the sampling has holes wider than about 2 K_P h_P the external marking
///    leaks inside and phi0 is a thin shell around the points, which the first
///    iterations destroy ("the zero level set vanished"); a K_P larger than
///    needed closes handles narrower than 2 K_P h_P. For every K of a ladder,
///    the nodes enclosed by the initial surface (d >= K h_P but not reached by
///    the marking) are counted on run 1's grid from one bottleneck computation
///    (outsideBottleneck); the K enclosing the most nodes is chosen: the
///    smallest K past the closing of the holes, since a larger K only erodes
///    the enclosed volume. A cloud that encloses nothing at any K (an open
///    sheet, a thin tube) keeps the thesis's K_P = 2.

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Context.h"
#include "sltk/recon/GridPlan.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sltk
{

/// The default memory budget when C_dx is automatic: a laptop's share with room
/// for ParaView (the Stanford bunny: C_dx about 2.1, 0.74 GB peak).
constexpr std::uint64_t AutomaticMemoryBudget = std::uint64_t(1) << 30;

/// Thinning cell in density spacings (CloudSpacing.h) of an automatic thinning:
/// the value chosen by hand on the merged Stanford bunny scans.
constexpr double AutomaticThinningFactor = 2.5;

/// The automatic interpolator (ReconstructionOptions::Interpolator empty): the
/// least-squares Q1 (5.5) on a cloud whose noise (CloudNoise.h, in h_P) is below
/// this, WENO3 otherwise. Measured with no options (Documentation/Profile.md): the
/// least squares is 0.46-0.86 of WENO3's Chamfer distance on the clean shared clouds
/// (noise 0.00-0.04) and on the merged scans with their noise projected away, 1.02
/// on the bunny with noise of 0.1 h_P (noise 0.11), 1.14 and 1.16 at 0.27 and on
/// the merged scans (0.38): its linear fit damps no grid-scale bump at the points,
/// where the model's own smoothing vanishes (d = 0 in (4.24)). The value lies
/// between the two groups, with WENO3 where a cloud is in doubt.
constexpr double AutomaticInterpolatorNoise = 0.08;

/// The K_P tried, from the thesis's default 2 to 32.
const std::vector<double>& outsideFactorLadder();

/// The ladder's next K_P above `factor` (a run that lost its zero level set
/// restarts with it), or 0 when there is none.
double nextOutsideFactor(double factor);

/// The K_P for which run 1's grid leaves room: the next rung above `factor`, so
/// that one restart fits.
double outsideFactorWithRestart(double factor);

/// The first rung tried for run 1's C_dx: the smallest K_P >= 2 C_dx, an
/// initial surface at least two of run 1's cells from the cloud as the thesis's
/// K_P = 2 at C_dx = 1 (4.4.4); when a memory budget coarsens the grid, a
/// thinner one loses the features thinner than a cell (the dragon's spikes
/// at C_dx 3.3: Documentation/Numerics.md, "Automatic parameters"). The last
/// rung when none is that large.
size_t firstOutsideRung(double cellSizeFactor);

struct OutsideFactorChoice
{
  double Factor = 2.0;              ///< the chosen K_P
  size_t FirstRung = 0;             ///< the first rung tried (firstOutsideRung)
  std::vector<Index> EnclosedNodes; ///< per ladder K: nodes with d >= K h_P the marking does not reach
  Index ProbeNodes = 0;             ///< nodes of the grid it was measured on
  double ProbeSpacing = 0.0;        ///< its dx
};

/// Chooses K_P for the cloud of `locator` (unit box, spacing h_P) on a grid of
/// spacing dx around `bounds` (run 1's: dx = C_dx h_P); with one sparsity factor
/// per point, for the local offset K_P h_P rho (LocalOffset.h): the rung from
/// firstOutsideRung(C_dx) on whose initial surface encloses the most nodes.
template <int D>
Status chooseOutsideFactor(const PointLocator<D>& locator, const Box<D>& bounds, double cloudSpacing, double dx,
  const std::vector<double>& sparsity, const Context& ctx, OutsideFactorChoice& choice);

/// chooseOutsideFactor() for a cloud spread over the ranks by owners
/// (PointOwners.h), with one sparsity factor per held point
/// (sparsityFactorsOnRanks) or none on every rank: every rank holds the probe
/// grid whole (at most 4M nodes), its distance and local offset are the
/// one-rank fields bit for bit (distanceToCloudOnRanks,
/// locallyScaledDistanceOnRanks), and every rank computes the same choice. Collective.
template <int D>
Status chooseOutsideFactorOnRanks(const OwnedPoints<D>& points, const Box<D>& bounds, double cloudSpacing, double dx,
  const std::vector<double>& sparsity, const Communicator& comm, const Context& ctx, OutsideFactorChoice& choice);

/// The ladder of automatic C_dx values: 1, CellSizeLadderStep, CellSizeLadderStep^2, ...
constexpr double CellSizeLadderStep = 1.02;

/// The smallest C_dx >= 1 on the ladder (steps of 2%) whose grids `options` (budget
/// included) accepts; fails when none up to 1e4 does.
template <int D>
Status chooseCellSizeFactor(const Box<D>& bounds, double cloudSpacing, GridPlanOptions options, double& cellSizeFactor);

extern template Status chooseOutsideFactor(const PointLocator<2>&, const Box<2>&, double, double,
  const std::vector<double>&, const Context&, OutsideFactorChoice&);
extern template Status chooseOutsideFactor(const PointLocator<3>&, const Box<3>&, double, double,
  const std::vector<double>&, const Context&, OutsideFactorChoice&);
extern template Status chooseOutsideFactorOnRanks(const OwnedPoints<2>&, const Box<2>&, double, double,
  const std::vector<double>&, const Communicator&, const Context&, OutsideFactorChoice&);
extern template Status chooseOutsideFactorOnRanks(const OwnedPoints<3>&, const Box<3>&, double, double,
  const std::vector<double>&, const Communicator&, const Context&, OutsideFactorChoice&);
extern template Status chooseCellSizeFactor(const Box<2>&, double, GridPlanOptions, double&);
extern template Status chooseCellSizeFactor(const Box<3>&, double, GridPlanOptions, double&);

} // namespace sltk
