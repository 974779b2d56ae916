// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Reinitialise.h
/// Narrow-band reinitialisation of a level-set function to a signed distance
/// function (thesis 1.5, Algorithm 1 step (e)): the PDE (1.30) with the sign
/// (1.31), solved to steady state with Godunov's (1.35) or the upwind (1.32)
/// scheme, after the constrained explicit step on the nodes next to the front
/// (1.38)-(1.45) by default (ReinitOptions).
///
/// The band is a list of node indices k in [0, nodeCount) in x-fastest order
/// (GridField::nodeIndex), e.g. the reinitialisation band (1.52)-(1.53), without
/// duplicates. Only band nodes are written; every other value (nodes outside the
/// band, ghost layers) is left untouched. Nodes outside the band are read as
/// boundary data; beyond the grid the boundary policy is applied on the fly
/// (ReinitStencil), so the ghost layers are not read either: call fillGhosts()
/// afterwards if they are needed.
///
/// Jacobi updates into a buffer make the result bit-identical for any number of
/// threads. Work and memory (25 bytes per band node, 33 when the steps are
/// skewed) are proportional to the band.
/// One process steps a band of ReinitWorkspace::SkewedBandNodes nodes or more in
/// skewed rounds of up to 10 steps (Documentation/Profile.md, "The pseudo-time
/// steps in skewed waves"): the same values bit for bit; the interrupter is
/// then asked once a round. On Aborted (interrupter) phi holds the values of the
/// last completed step; on a non-finite value, those of the step that made it.

#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/levelset/ReinitOptions.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace sltk
{

/// A distributed solve's part (ReinitialiseSlabs.h); empty members: one process.
struct ReinitStepExchange
{
  /// The ranks' common status from this rank's (the checks and allocations
  /// before the first step), so that no rank steps while another has failed.
  std::function<Status(const Status&)> Agree;
  /// Between two pseudo-time steps: given this rank's largest change of the
  /// step and whether it was told to stop, exchanges what the ranks share and
  /// returns the change the stopping test uses (+infinity when any rank's was
  /// not finite), `interrupted` set when any rank was told to stop.
  std::function<double(double localChange, bool& interrupted)> AfterStep;
};

/// The per-band-node arrays of reinitialise() (25 bytes a node, 33 with skewed
/// steps). A caller that
/// reinitialises again and again (the iterations of a run) keeps one, so that the
/// arrays' pages are allocated and faulted in once, not at every call
/// (Documentation/Profile.md, "Page faults of the per-iteration arrays").
struct ReinitWorkspace
{
  std::vector<Index> Offset;       ///< storage offset of each band node
  std::vector<double> Coefficient; ///< s of (1.31), or the target distance of X
  std::vector<double> Next;        ///< Jacobi buffer
  std::vector<std::uint8_t> Role;  ///< each node's role
  std::vector<double> ChunkChange; ///< per-chunk largest |change|
  std::vector<double> Saved;       ///< the band's values before a round of skewed steps
  /// One process steps a band of at least this many nodes in skewed rounds (time skewing over
  /// its planes, the same values bit for bit; smaller bands stay in the caches between steps).
  Index SkewedBandNodes = Index(1) << 20;
};

/// `workspace`: the arrays to reuse (null: the call's own).
template <int D>
Status reinitialise(GridField<D>& phi, const Index* band, Index bandSize, const ReinitOptions& options,
  const Context& ctx, ReinitReport* report = nullptr, const ReinitStepExchange& exchange = {},
  ReinitWorkspace* workspace = nullptr);

template <int D>
Status reinitialise(GridField<D>& phi, const std::vector<Index>& band, const ReinitOptions& options, const Context& ctx,
  ReinitReport* report = nullptr)
{
  return reinitialise<D>(phi, band.data(), static_cast<Index>(band.size()), options, ctx, report);
}

extern template Status reinitialise(GridField<2>&, const Index*, Index, const ReinitOptions&, const Context&,
  ReinitReport*, const ReinitStepExchange&, ReinitWorkspace*);
extern template Status reinitialise(GridField<3>&, const Index*, Index, const ReinitOptions&, const Context&,
  ReinitReport*, const ReinitStepExchange&, ReinitWorkspace*);

} // namespace sltk
