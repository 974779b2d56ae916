// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LocalOffset.h
/// Beyond the thesis: run 1's initial surface at K_P h_P rho(x) from the cloud
/// instead of K_P h_P (4.4.4), rho the sparsity factor of the point nearest to
/// x (cloud/LocalSpacing.h). The outside marking and the sweeping of
/// CloudInitialData.h run unchanged on the scaled distance u = d / rho, whose
/// level set u = K_P h_P is d = K_P h_P rho; where the cloud is evenly sampled
/// rho = 1 and u = d (Documentation/Numerics.md, "Local offset").

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

#include <vector>

namespace sltk
{

/// u = d / rho(x) on every node of `distance` with d < reach, rho(x) the factor of
/// the nearest point: queried within two cells of the cloud, carried outwards
/// along the steepest descent of d beyond (O(n log n), no query far from the
/// cloud); farther nodes get d / max(rho), at least reach / max(rho): pass reach
/// = (largest K_P h_P) * max(rho) so that they stay outside every initial
/// surface. `scaled` takes the grid and ghosts of `distance`.
template <int D>
Status locallyScaledDistance(const GridField<D, double>& distance, const PointLocator<D>& locator,
  const std::vector<double>& sparsity, double reach, const Context& ctx, GridField<D, double>& scaled);

/// The same on this rank's window of a slab decomposition (grid/Slabs.h, the
/// ghost rows of `distance` current): the descent is carried on the window and
/// the ghost rows exchanged until none changes on any rank, so u is the
/// one-rank u (a descent path may cross slabs). A collective call;
/// locallyScaledDistance is its one-rank call (wholeSlab).
template <int D>
Status locallyScaledDistanceSlabs(const GridField<D, double>& distance, const PointLocator<D>& locator,
  const std::vector<double>& sparsity, double reach, const SlabPlan& slab, const Communicator& comm, const Context& ctx,
  GridField<D, double>& scaled);

/// The largest factor of every rank's own points (one per held point in
/// `sparsity`; 0 when there are none). Collective.
template <int D>
double largestOwnedFactor(const OwnedPoints<D>& points, const std::vector<double>& sparsity, const Communicator& comm);

/// locallyScaledDistance() on a grid every rank holds whole (`distance`, the
/// same on every rank: distanceToCloudOnRanks), from a cloud spread over the
/// ranks by owners with one factor per held point (sparsityFactorsOnRanks):
/// each node near the cloud takes the factor of the nearest of every rank's
/// own points (ties by the lowest global index, as one rank's locator), by
/// three reductions over those nodes; the rest is the one-rank arithmetic, so
/// the result is the one-rank field bit for bit. Collective.
template <int D>
Status locallyScaledDistanceOnRanks(const GridField<D, double>& distance, const OwnedPoints<D>& points,
  const std::vector<double>& sparsity, double reach, const Communicator& comm, const Context& ctx,
  GridField<D, double>& scaled);

extern template Status locallyScaledDistance(const GridField<2, double>&, const PointLocator<2>&,
  const std::vector<double>&, double, const Context&, GridField<2, double>&);
extern template Status locallyScaledDistance(const GridField<3, double>&, const PointLocator<3>&,
  const std::vector<double>&, double, const Context&, GridField<3, double>&);
extern template double largestOwnedFactor(const OwnedPoints<2>&, const std::vector<double>&, const Communicator&);
extern template double largestOwnedFactor(const OwnedPoints<3>&, const std::vector<double>&, const Communicator&);
extern template Status locallyScaledDistanceOnRanks(const GridField<2, double>&, const OwnedPoints<2>&,
  const std::vector<double>&, double, const Communicator&, const Context&, GridField<2, double>&);
extern template Status locallyScaledDistanceOnRanks(const GridField<3, double>&, const OwnedPoints<3>&,
  const std::vector<double>&, double, const Communicator&, const Context&, GridField<3, double>&);
extern template Status locallyScaledDistanceSlabs(const GridField<2, double>&, const PointLocator<2>&,
  const std::vector<double>&, double, const SlabPlan&, const Communicator&, const Context&, GridField<2, double>&);
extern template Status locallyScaledDistanceSlabs(const GridField<3, double>&, const PointLocator<3>&,
  const std::vector<double>&, double, const SlabPlan&, const Communicator&, const Context&, GridField<3, double>&);

} // namespace sltk
