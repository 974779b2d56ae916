// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReinitialiseSlabs.h
/// The narrow-band reinitialisation (Reinitialise.h, thesis 1.5 and 4.4.5) on
/// the slabs of a distributed grid (grid/Slabs.h): each rank steps the band
/// nodes of its owned rows; after the explicit step on the front and after
/// every pseudo-time step the ghost rows are exchanged (SlabExchange.h; on one
/// rank there are none, and the steps are one process's, Reinitialise.h), and
/// the largest change (the stopping test) and a stop on any rank are reduced
/// over the ranks, so every rank stops at the same step. A Jacobi step reads
/// its neighbours' previous values only, so with the ghost rows current the
/// owned values are bitwise the one-rank reinitialisation's. A pseudo-time
/// step reads one row beyond (ReinitStencil.h axes), so only the ghost row
/// next to the owned rows is exchanged; the classification on entry reads the
/// 3^D blocks of the neighbours (1.44), two rows beyond, so on entry the
/// ReinitEntryRows ghost rows next to the owned rows must be current. The
/// farther ghost rows keep their values: exchange them afterwards if a wider
/// stencil follows.

#include "sltk/exec/Communicator.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/levelset/NarrowBand.h"
#include "sltk/levelset/Reinitialise.h"

#include <cmath>
#include <limits>

namespace sltk
{

/// The ghost rows next to the owned rows that reinitialiseSlabs reads on entry.
constexpr Index ReinitEntryRows = 2;

/// `window`: this rank's rows slab.First .. slab.Stop - 1 with its ghost rows
/// current; `ownedBand`: the band nodes of the owned rows (window numbering).
/// A collective call.
template <int D>
Status reinitialiseSlabs(GridField<D>& window, const NodeList& ownedBand, const SlabPlan& slab,
  const Communicator& comm, const ReinitOptions& options, const Context& ctx, ReinitReport* report = nullptr,
  ReinitWorkspace* workspace = nullptr)
{
  ReinitStepExchange exchange;
  exchange.Agree = [&](const Status& status) { return comm.agree(status); };
  if (comm.size() == 1) // no rows to exchange: the steps of one process (skewed on a large band)
  {
    return reinitialise<D>(
      window, ownedBand.data(), static_cast<Index>(ownedBand.size()), options, ctx, report, exchange, workspace);
  }
  exchange.AfterStep = [&](double change, bool& interrupted)
  {
    exchangeGhostRows(window, slab, comm, nullptr, 1);
    double reduced[2] = { std::isfinite(change) ? change : std::numeric_limits<double>::infinity(),
      interrupted ? 1.0 : 0.0 };
    comm.allReduce(reduced, 2, ReduceOp::Max);
    interrupted = reduced[1] > 0.0;
    return reduced[0];
  };
  return reinitialise<D>(
    window, ownedBand.data(), static_cast<Index>(ownedBand.size()), options, ctx, report, exchange, workspace);
}

} // namespace sltk
