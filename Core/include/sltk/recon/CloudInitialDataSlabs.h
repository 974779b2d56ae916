// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudInitialDataSlabs.h
/// The initial level set phi0 (CloudInitialData.h, thesis 4.4.4) on the slabs
/// of a distributed grid (sltk/grid/Slabs.h), as the thesis iterates its
/// marking with halo exchanges (Fig. 4.4): every rank marks its window from
/// the whole grid's boundary until nothing changes, then the ranks OR their
/// edge rows' marks into the neighbours' ghost rows; the first round in which
/// no rank received a new mark ends it. A mark is never wrong (each is reached
/// from the boundary through nodes with d >= gamma_P), so the marks are
/// exactly the one-rank marking's for the same distances. The sweep of step 2
/// runs on slabs (FastSweepingSlabs.h).

#include "sltk/exec/Communicator.h"
#include "sltk/grid/Slabs.h"
#include "sltk/recon/CloudInitialData.h"

namespace sltk
{

/// Step 1 on `distance`, this rank's window of `slab` in a grid of `rows` rows
/// along the last axis (the ghost rows hold the neighbours' distances, as
/// distanceToCloudSlabs leaves them). `rounds`: the rounds of passes over all
/// axes, summed over the exchanges. A collective call; markExternal is its
/// one-rank call (wholeSlab).
template <int D>
Status markExternalSlabs(const GridField<D, double>& distance, double threshold, const SlabPlan& slab, Index rows,
  const Communicator& comm, const Context& ctx, std::vector<std::uint8_t>& external, int* rounds = nullptr);

/// Steps 1-2 on the window: phi0 of the window (rows slab.First .. slab.Stop - 1);
/// cloudInitialData is its one-rank call.
template <int D>
Status cloudInitialDataSlabs(const GridField<D, double>& distance, double threshold, const SlabPlan& slab, Index rows,
  const Communicator& comm, const Context& ctx, GridField<D, double>& phi0, const InitialDataOptions& options = {},
  InitialDataReport* report = nullptr);

extern template Status markExternalSlabs(const GridField<2, double>&, double, const SlabPlan&, Index,
  const Communicator&, const Context&, std::vector<std::uint8_t>&, int*);
extern template Status markExternalSlabs(const GridField<3, double>&, double, const SlabPlan&, Index,
  const Communicator&, const Context&, std::vector<std::uint8_t>&, int*);
extern template Status cloudInitialDataSlabs(const GridField<2, double>&, double, const SlabPlan&, Index,
  const Communicator&, const Context&, GridField<2, double>&, const InitialDataOptions&, InitialDataReport*);
extern template Status cloudInitialDataSlabs(const GridField<3, double>&, double, const SlabPlan&, Index,
  const Communicator&, const Context&, GridField<3, double>&, const InitialDataOptions&, InitialDataReport*);

} // namespace sltk
