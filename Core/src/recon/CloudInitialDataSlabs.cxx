// SPDX-License-Identifier: BSD-3-Clause
// markExternalSlabs() and cloudInitialDataSlabs() (CloudInitialDataSlabs.h).
#include "sltk/recon/CloudInitialDataSlabs.h"

#include "ExternalMarking.h"
#include "sltk/levelset/FastSweepingSlabs.h"

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
  const Index below = slab.Begin - slab.First, above = slab.Stop - slab.End; // ghost rows on each side
  const int rank = comm.rank(), size = comm.size();
  const int down = rank > 0 ? rank - 1 : -1, up = rank + 1 < size ? rank + 1 : -1;
  std::vector<std::uint8_t> receive;
  int round = 0;
  for (;; ++round)
  {
    SLTK_RETURN_IF_ERROR(comm.agree(marking::spreadExternal(distance, threshold, ctx, external, nullptr)));
    // My first owned rows' marks down and the rows above mine back, then my last owned rows' up and below's back.
    bool received = false;
    for (const bool toDown : { true, false })
    {
      const Index sentFirst = toDown ? below : g.Dims[D - 1] - 2 * above;
      const Index sentRows = toDown ? below : above, gotRows = toDown ? above : below;
      const Index ghostFirst = toDown ? g.Dims[D - 1] - above : 0;
      receive.assign(static_cast<size_t>(gotRows * rowNodes), 0);
      comm.sendReceive(external.data() + sentFirst * rowNodes, static_cast<size_t>(sentRows * rowNodes),
        toDown ? down : up, receive.data(), receive.size(), toDown ? up : down);
      for (size_t k = 0; k < receive.size(); ++k)
      {
        std::uint8_t& mark = external[static_cast<size_t>(ghostFirst * rowNodes) + k];
        received = received || (receive[k] && !mark);
        mark = static_cast<std::uint8_t>(mark | receive[k]);
      }
    }
    if (comm.allReduce(static_cast<std::int64_t>(received ? 1 : 0), ReduceOp::Max) == 0)
    {
      break;
    }
  }
  if (rounds)
  {
    *rounds = round + 1;
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
