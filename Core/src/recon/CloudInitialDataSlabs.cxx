// SPDX-License-Identifier: BSD-3-Clause
// markExternalSlabs() and cloudInitialDataSlabs() (CloudInitialDataSlabs.h).
#include "sltk/recon/CloudInitialDataSlabs.h"

#include "ExternalMarking.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/levelset/FastSweepingSlabs.h"

#include <algorithm>

#include <cstdint>
#include <vector>

namespace sltk
{

template <int D>
Status markExternalSlabs(const GridField<D, double>& distance, double threshold, const SlabPlan& slab, Index rows,
  const Communicator& comm, const Context& ctx, std::vector<std::uint8_t>& external, int* rounds)
{
  const GridSpec<D>& g = distance.spec();
  Status input = Status::ok();
  if (!(threshold > 0.0) || !std::isfinite(threshold))
  {
    input = Status::invalidArgument("the threshold gamma_P = K_P h_P must be positive and finite");
  }
  else if (g.Dims[D - 1] != slab.windowRows() || (comm.size() > 1 && slab.Ghost < 1))
  {
    input = Status::invalidArgument("external marking on slabs: the window and the slab plan disagree");
  }
  SLTK_RETURN_IF_ERROR(comm.agree(input));
  marking::markBoundary(distance, slab.First, rows, ctx, external);
  const Index rowNodes = g.nodeCount() / g.Dims[D - 1];
  int passes = 0; // rounds of passes over all axes, summed over the exchanges
  for (;;)
  {
    int spread = 0;
    SLTK_RETURN_IF_ERROR(comm.agree(marking::spreadExternal(distance, threshold, ctx, external, &spread)));
    passes += spread;
    // The neighbours' marks OR-ed into my ghost rows: a mark is never wrong, so none is taken back.
    bool received = false;
    exchangeSlabRows<std::uint8_t>(
      slab, rowNodes, comm,
      [&](Index first, Index count, std::uint8_t* to)
      { std::copy_n(external.data() + first * rowNodes, count * rowNodes, to); },
      [&](Index first, Index count, const std::uint8_t* from)
      {
        for (Index k = 0; k < count * rowNodes; ++k)
        {
          std::uint8_t& mark = external[static_cast<size_t>(first * rowNodes + k)];
          received = received || (from[k] && !mark);
          mark = static_cast<std::uint8_t>(mark | from[k]);
        }
      });
    if (!comm.anyRank(received))
    {
      break;
    }
  }
  if (rounds)
  {
    *rounds = passes;
  }
  return Status::ok();
}

template <int D>
Status cloudInitialDataSlabs(const GridField<D, double>& distance, double threshold, const SlabPlan& slab, Index rows,
  const Communicator& comm, const Context& ctx, GridField<D, double>& phi0, const InitialDataOptions& options,
  InitialDataReport* report)
{
  SLTK_RETURN_IF_ERROR(comm.agree(marking::checkInitialDataOptions(options)));
  InitialDataReport local;
  std::vector<std::uint8_t> external;
  SLTK_RETURN_IF_ERROR(markExternalSlabs(distance, threshold, slab, rows, comm, ctx, external, &local.MarkingRounds));
  SLTK_RETURN_IF_ERROR(marking::initialDataFromMarks(distance, threshold, external, ctx, phi0, options, local,
    [&](GridField<D, double>& w, const std::vector<std::uint8_t>& frozen, int& cycles)
    {
      FastSweepingSlabsReport swept;
      const Status status = fastSweepSlabs(w, frozen, slab, comm, ctx, marking::sweepOptions(options), &swept);
      cycles = swept.Cycles;
      return status;
    }));
  if (report)
  {
    *report = local;
  }
  return Status::ok();
}

template Status markExternalSlabs(const GridField<2, double>&, double, const SlabPlan&, Index, const Communicator&,
  const Context&, std::vector<std::uint8_t>&, int*);
template Status markExternalSlabs(const GridField<3, double>&, double, const SlabPlan&, Index, const Communicator&,
  const Context&, std::vector<std::uint8_t>&, int*);
template Status cloudInitialDataSlabs(const GridField<2, double>&, double, const SlabPlan&, Index, const Communicator&,
  const Context&, GridField<2, double>&, const InitialDataOptions&, InitialDataReport*);
template Status cloudInitialDataSlabs(const GridField<3, double>&, double, const SlabPlan&, Index, const Communicator&,
  const Context&, GridField<3, double>&, const InitialDataOptions&, InitialDataReport*);

} // namespace sltk
