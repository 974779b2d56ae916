// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/Reconstruction.h"

#include "sltk/recon/ReconstructionInterpolator.h"

#include "RunLoop.h"
#include "SlabRuns.h"

namespace sltk
{

template <int D>
Status reconstruct(
  const ReconstructionPlan<D>& plan, const Context& ctx, ReconstructionResult<D>& result, const Communicator& comm)
{
  const Status status = reconstructWithRecoveries(plan, ctx, comm, result,
    [&](const ReconstructionOptions& options, const std::vector<GridSpec<D>>& grids)
    {
      return withReconstructionInterpolator<D>(options,
        [&](auto tag)
        {
          SlabRuns<D, typename decltype(tag)::type> runs(plan, options, grids, ctx, comm);
          return runAlgorithm1(runs, plan, options, ctx, result);
        });
    });
  plan.Box.toUser(result.SignedDistance);
  plan.Box.toUser(result.Distance);
  result.WholeGrid = plan.Box.toUser(result.WholeGrid);
  return status;
}

template <int D>
Status reconstruct(
  const PointCloud<D>& cloud, const ReconstructionOptions& options, const Context& ctx, ReconstructionResult<D>& result)
{
  result = ReconstructionResult<D>{};
  ReconstructionPlan<D> plan;
  SLTK_RETURN_IF_ERROR(planReconstruction(cloud, options, ctx, plan));
  return reconstruct(plan, ctx, result);
}

template Status reconstruct(
  const PointCloud<2>&, const ReconstructionOptions&, const Context&, ReconstructionResult<2>&);
template Status reconstruct(
  const PointCloud<3>&, const ReconstructionOptions&, const Context&, ReconstructionResult<3>&);
template Status reconstruct(
  const ReconstructionPlan<2>&, const Context&, ReconstructionResult<2>&, const Communicator&);
template Status reconstruct(
  const ReconstructionPlan<3>&, const Context&, ReconstructionResult<3>&, const Communicator&);

} // namespace sltk
