// SPDX-License-Identifier: BSD-3-Clause
// fastSweepSlabs(): fast sweeping with a halo exchange per round (FastSweepingSlabs.h).
#include "sltk/levelset/FastSweepingSlabs.h"

#include "sltk/grid/SlabExchange.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sltk
{

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
  FastSweepingSlabsReport total;
  for (int round = 0; round < std::max(1, options.MaxCycles); ++round)
  {
    FastSweepingReport swept;
    SLTK_RETURN_IF_ERROR(comm.agree(fastSweep(window, fixed, ctx, options, &swept)));
    total.Rounds = round + 1;
    total.Cycles += swept.Cycles;
    total.Converged = total.Converged && swept.Converged;
    bool changed = false;
    exchangeGhostRows(window, slab, comm, &changed);
    if (!comm.anyRank(changed))
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
