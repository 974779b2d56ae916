// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ReconstructionSummary.h"

#include <algorithm>

namespace sltk
{

template <int D>
ReconstructionSummary summarize(const ReconstructionResult<D>& result)
{
  ReconstructionSummary summary;
  static_cast<ReconstructionReport&>(summary) = result;
  for (const RunRecord<D>& run : result.Runs)
  {
    RunSummary r;
    static_cast<RunFigures&>(r) = run;
    std::copy(run.Grid.Dims.begin(), run.Grid.Dims.end(), r.GridDimensions.begin());
    summary.Runs.push_back(r);
  }
  return summary;
}

template ReconstructionSummary summarize(const ReconstructionResult<2>&);
template ReconstructionSummary summarize(const ReconstructionResult<3>&);

} // namespace sltk
