// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ReconstructionSummary.h"

#include <algorithm>

namespace sltk
{

template <int D>
ReconstructionSummary summarize(const ReconstructionResult<D>& result, const std::array<double, 3>& frame)
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
  for (const MissedPlace<D>& place : result.MissedPlaces)
  {
    MissedPlace<3> p;
    p.Points = place.Points;
    p.Nearby = place.Nearby;
    for (int a = 0; a < D; ++a) // as the warnings name them (RunLoop.h, describeMissedPlaces)
    {
      p.Centre[a] = place.Centre[a] + frame[static_cast<size_t>(a)];
      p.Lower[a] = place.Lower[a] + frame[static_cast<size_t>(a)];
      p.Upper[a] = place.Upper[a] + frame[static_cast<size_t>(a)];
    }
    summary.MissedPlaces.push_back(p);
  }
  return summary;
}

template ReconstructionSummary summarize(const ReconstructionResult<2>&, const std::array<double, 3>&);
template ReconstructionSummary summarize(const ReconstructionResult<3>&, const std::array<double, 3>&);

} // namespace sltk
