// SPDX-License-Identifier: BSD-3-Clause
// fastSweepSlabs(): fast sweeping with a halo exchange per round (FastSweepingSlabs.h).
#include "sltk/levelset/FastSweepingSlabs.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sltk
{
namespace
{
/// Reads (write = false) or writes the window's local rows [first, first + count) of the last axis to/from `buffer`.
template <int D>
void moveRows(GridField<D, double>& window, Index first, Index count, std::vector<double>& buffer, bool write)
{
  Index rowNodes = 1;
  for (int a = 0; a + 1 < D; ++a)
  {
    rowNodes *= window.spec().Dims[a];
  }
  buffer.resize(static_cast<size_t>(count * rowNodes));
  for (Index k = 0; k < count * rowNodes; ++k)
  {
    double& value = window(window.nodeIndex(first * rowNodes + k));
    if (write)
    {
      value = buffer[static_cast<size_t>(k)];
    }
    else
    {
      buffer[static_cast<size_t>(k)] = value;
    }
  }
}
} // namespace

template <int D>
Status fastSweepSlabs(GridField<D, double>& window, const std::vector<std::uint8_t>& frozen, const SlabPlan& slab,
  const Communicator& comm, const Context& ctx, const FastSweepingOptions& options, FastSweepingSlabsReport* report)
{
  const Index rows = window.spec().Dims[D - 1];
  Status shape = Status::ok();
  if (rows != slab.windowRows() || static_cast<Index>(frozen.size()) != window.spec().nodeCount() ||
    (comm.size() > 1 && slab.Ghost < 1))
  {
    shape = Status::invalidArgument("fast sweeping on slabs: the window, its mask and the slab plan disagree");
  }
  SLTK_RETURN_IF_ERROR(comm.agree(shape));
  // The ghost rows hold the neighbours' values: data for this rank's sweeps.
  const Index below = slab.Begin - slab.First, above = slab.Stop - slab.End; // ghost rows on each side
  const Index rowNodes = window.spec().nodeCount() / rows;
  std::vector<std::uint8_t> fixed = frozen;
  std::fill(fixed.begin(), fixed.begin() + static_cast<std::ptrdiff_t>(below * rowNodes), std::uint8_t(1));
  std::fill(fixed.end() - static_cast<std::ptrdiff_t>(above * rowNodes), fixed.end(), std::uint8_t(1));
  const int rank = comm.rank(), size = comm.size();
  const int down = rank > 0 ? rank - 1 : -1, up = rank + 1 < size ? rank + 1 : -1;
  FastSweepingSlabsReport total;
  std::vector<double> send, receive, old;
  for (int round = 0; round < std::max(1, options.MaxCycles); ++round)
  {
    FastSweepingReport swept;
    SLTK_RETURN_IF_ERROR(comm.agree(fastSweep(window, fixed, ctx, options, &swept)));
    total.Rounds = round + 1;
    total.Cycles += swept.Cycles;
    total.Converged = total.Converged && swept.Converged;
    // My first owned rows down and the rows above mine back, then my last owned rows up and the rows below back.
    bool changed = false;
    for (const bool toDown : { true, false })
    {
      const int to = toDown ? down : up, from = toDown ? up : down;
      // My ghost rows on a side are as many as the neighbour's on mine (both Ghost, none at the domain's edge).
      const Index sentRows = toDown ? below : above, gotRows = toDown ? above : below;
      moveRows(window, toDown ? below : rows - above - sentRows, sentRows, send, false);
      receive.resize(static_cast<size_t>(gotRows * rowNodes));
      comm.sendReceive(
        send.data(), send.size() * sizeof(double), to, receive.data(), receive.size() * sizeof(double), from);
      const Index ghostFirst = toDown ? rows - above : 0;
      moveRows(window, ghostFirst, gotRows, old, false);
      changed = changed || old != receive;
      moveRows(window, ghostFirst, gotRows, receive, true);
    }
    if (comm.allReduce(static_cast<std::int64_t>(changed ? 1 : 0), ReduceOp::Max) == 0)
    {
      break;
    }
  }
  if (report)
  {
    *report = total;
  }
  return Status::ok();
}

template Status fastSweepSlabs(GridField<2, double>&, const std::vector<std::uint8_t>&, const SlabPlan&,
  const Communicator&, const Context&, const FastSweepingOptions&, FastSweepingSlabsReport*);
template Status fastSweepSlabs(GridField<3, double>&, const std::vector<std::uint8_t>&, const SlabPlan&,
  const Communicator&, const Context&, const FastSweepingOptions&, FastSweepingSlabsReport*);

} // namespace sltk
