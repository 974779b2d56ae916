// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file DistributedHjbSolver.h
/// The scheme (3.7) of a formula-defined problem (ExpressionProblem.h) on the
/// ranks of a communicator, as the thesis distributes its solvers with PETSc
/// (4.4.1): the grid is cut into slabs of the last axis, each rank steps its
/// slab plus G ghost rows on each side with the serial scheme, and after every
/// step sends its first and last G owned rows to its neighbours (one
/// sendReceive each way, no per-foot message).
///
/// Why G rows suffice: the value at an owned node after a step reads u^k only
/// around the foot of its characteristic, at most |f_D| dt (the last axis'
/// component) from the node, within the interpolation stencil (StencilRows).
/// G = ceil(1.25 max|f_D| dt / dx) + StencilRows, with max|f_D| sampled over
/// every node, the sampled controls (corners/centre/poles of A) and t = 0, T/2,
/// T: a bound for the formulas users write (linear in the control, smooth in
/// x and t), not a proof for every formula. Ghost rows are stepped too (they
/// are wrong at the slab's edge) and overwritten by the exchange.
///
/// Every rank's owned values are bitwise those of the serial solve: the slab is
/// a window of the whole grid (GridSpec::Offset), so its node coordinates, dx
/// and dt are the whole grid's, and the scheme reads the same values.
/// Memory: each rank allocates its slab plus 2G rows (checked per rank); the
/// result is gathered whole on every rank (the writer's copy).
/// After every step the ranks agree on the status (Communicator::agree): a
/// failure on one rank ends all of them with its message, without a hang.

#include "sltk/exec/Communicator.h"
#include "sltk/hjb/HjbSolver.h"

namespace sltk
{

/// Interpolation stencil reach in rows (WENO3, CWENO and CWENOZ read at most
/// two nodes on each side of the cell of the foot).
constexpr Index HjbStencilRows = 3;

/// A solver of the whole grid (grid(), result()) whose work and memory are
/// split over `comm`'s ranks. result() gathers the value function (and the
/// reachable set) on every rank, and reduces the errors against the exact
/// solution over the owned nodes. One rank: makeExpressionSolver(). The last
/// axis may not be periodic; every rank needs at least G owned rows.
Status makeDistributedExpressionSolver(
  const HjbExpressionSpec& spec, const Communicator& comm, std::unique_ptr<HjbSolver>& solver);

} // namespace sltk
