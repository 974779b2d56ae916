// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file DistributedHjbSolver.h
/// The scheme (3.7) of a formula-defined problem (ExpressionProblem.h) or a
/// thesis test (PresetRun.h) on the ranks of a communicator, as the thesis distributes its solvers with PETSc
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
/// A periodic last axis (Test 3, `--periodic z`) wraps the slabs: the first
/// and last ranks are neighbours, and their ghost rows past the axis' ends lie
/// a period away, in a window that does not wrap itself (its end rows are
/// ghost rows). The first rank's window starts at row -G, so its feet's cell
/// coordinates are s + G where the serial solve computes s (or wraps s + N),
/// which round differently: the values agree to rounding (about 1e-15), not bitwise.
/// Memory: each rank allocates its slab plus 2G rows (checked per rank) and
/// holds only the output block it asks for (HjbSolver::resultBlock).
/// After every step the ranks agree on the status (Communicator::agree): a
/// failure on one rank ends all of them with its message, without a hang.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/Slabs.h"
#include "sltk/hjb/HjbSolver.h"
#include "sltk/hjb/PresetRun.h"

#include <functional>

namespace sltk
{

/// Interpolation stencil reach in rows (WENO3, CWENO and CWENOZ read at most
/// two nodes on each side of the cell of the foot).
constexpr Index HjbStencilRows = 3;

/// The exact solution v(t, x) (x: three coordinates, unused axes 0).
using ExactSolution = std::function<double(double t, const double* x)>;

/// The slabs of `grid` over `comm`'s ranks for feet that move at most
/// `speed` dt along the last axis in a step (G above); refuses fewer than G
/// rows a rank ("use fewer ranks or more nodes"). `periodic`: the last axis
/// wraps, so the first and last ranks exchange rows too (SlabPlan::Periodic).
Status planSlabs(
  const HjbGrid& grid, double speed, double dt, const Communicator& comm, SlabPlan& plan, bool periodic = false);

/// The distributed solver of `whole` from this rank's solver on its window
/// (`window`: the rows [slab.First, slab.Stop) at the whole grid's
/// coordinates); `exact` may be empty; `reachable`: the window keeps the
/// reachable set (3.40).
std::unique_ptr<HjbSolver> makeDistributedSolver(std::unique_ptr<HjbSolver> window, const Communicator& comm,
  const HjbGrid& whole, ExactSolution exact, const SlabPlan& slab, bool reachable);

/// A solver of the whole grid (grid(), result()) whose work and memory are
/// split over `comm`'s ranks. resultBlock() sends each rank the nodes it asks
/// for (result(): the whole grid on every rank); the errors against the exact
/// solution are reduced over the owned nodes. One rank: makeExpressionSolver(). Every
/// rank needs at least G owned rows.
Status makeDistributedExpressionSolver(
  const HjbExpressionSpec& spec, const Communicator& comm, std::unique_ptr<HjbSolver>& solver);

/// The same for a thesis test (PresetRun.h), every one split (the feet's
/// speed along the last axis is bounded in closed form: pi, pi/2, 2, 2.2, 1
/// for Tests 1-5; Test 3's axis is periodic).
Status makeDistributedPresetSolver(
  const PresetRunOptions& options, const Communicator& comm, std::unique_ptr<HjbSolver>& solver);

} // namespace sltk
