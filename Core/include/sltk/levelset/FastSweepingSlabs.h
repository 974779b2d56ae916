// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FastSweepingSlabs.h
/// Fast sweeping (FastSweeping.h) on the slabs of a distributed grid
/// (sltk/grid/Slabs.h), as the thesis iterates its sweeps with halo exchanges
/// until nothing changes (4.4.1, Fig. 4.4): every rank sweeps its window (its
/// owned rows plus the ghost rows on each inner side, held fixed: the
/// neighbours' values) until it converges, then the ranks exchange their edge
/// rows; the first round in which no rank's ghost rows changed ends it. One
/// exchange of the ghost rows per round, never a message per node.
///
/// The discrete Eikonal solution is unique (each value is the same update of
/// smaller neighbour values), so with Tolerance 0 every owned value is the
/// one-rank sweep's whatever the rank count, up to rounding: the update's
/// square root is not monotone in floating point, so the sweeps may settle in
/// the last bits elsewhere (measured: 6.5e-14 relative at most, 2D and 3D,
/// 2-4 ranks). With Tolerance > 0 the sweeps may stop at other points below
/// the tolerance.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/Slabs.h"
#include "sltk/levelset/FastSweeping.h"

namespace sltk
{

struct FastSweepingSlabsReport
{
  int Rounds = 0;        ///< sweeps to local convergence, each followed by one exchange
  int Cycles = 0;        ///< this rank's cycles over all rounds
  bool Converged = true; ///< every round converged on every rank
};

/// Sweeps `window` (the nodes of slab.First .. slab.Stop - 1 along the last
/// axis; slab.Ghost >= 1) on every rank of `comm` (a collective call);
/// `frozen` as fastSweep(), one entry per node of the window. A failure or an
/// interruption on one rank ends every rank with the same status.
template <int D>
Status fastSweepSlabs(GridField<D, double>& window, const std::vector<std::uint8_t>& frozen, const SlabPlan& slab,
  const Communicator& comm, const Context& ctx, const FastSweepingOptions& options = {},
  FastSweepingSlabsReport* report = nullptr);

extern template Status fastSweepSlabs(GridField<2, double>&, const std::vector<std::uint8_t>&, const SlabPlan&,
  const Communicator&, const Context&, const FastSweepingOptions&, FastSweepingSlabsReport*);
extern template Status fastSweepSlabs(GridField<3, double>&, const std::vector<std::uint8_t>&, const SlabPlan&,
  const Communicator&, const Context&, const FastSweepingOptions&, FastSweepingSlabsReport*);

} // namespace sltk
