// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RunGridMemory.h
/// The run grids against the memory, for the plan's steps
/// (ReconstructionPlan.cxx; defined in RunGridMemory.cxx).
#include "sltk/exec/Context.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <cstdint>
#include <string>

namespace sltk
{

/// A number of a choice or refusal, three significant digits.
std::string planNumber(double value);

/// An automatic C_dx split over ranks: the one-rank C_dx while the windows of
/// the ranks on this machine fit, else the smallest of the ladder whose windows
/// fit. `po`: the grid options the one-rank C_dx was chosen with.
template <int D>
Status fitWindowsOnThisMachine(ReconstructionPlan<D>& plan, GridPlanOptions po);

/// The log line of an automatic C_dx (`oneRank`: the one-rank choice).
template <int D>
std::string cellSizeChoice(const ReconstructionPlan<D>& plan, std::uint64_t budget, double oneRank);

/// planRunGrids into plan.Grids; with an automatic C_dx split over ranks, the
/// ladder climbed on while the windows do not fit.
template <int D>
Status planFittingRunGrids(ReconstructionPlan<D>& plan, const Context& ctx);

extern template Status fitWindowsOnThisMachine(ReconstructionPlan<2>&, GridPlanOptions);
extern template Status fitWindowsOnThisMachine(ReconstructionPlan<3>&, GridPlanOptions);
extern template std::string cellSizeChoice(const ReconstructionPlan<2>&, std::uint64_t, double);
extern template std::string cellSizeChoice(const ReconstructionPlan<3>&, std::uint64_t, double);
extern template Status planFittingRunGrids(ReconstructionPlan<2>&, const Context&);
extern template Status planFittingRunGrids(ReconstructionPlan<3>&, const Context&);

} // namespace sltk
