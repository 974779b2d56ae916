// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbCustomProblem.h
/// `sltk hjb` options of a problem given by formulas (vtkCWENOHJBSolver's
/// Custom preset): their names, their help text, and setting them on the filter.

#include "Commands.h"

#include <string>
#include <vector>

class vtkCWENOHJBSolver;

namespace sltkcli
{

/// Valued options of a custom problem.
const std::vector<std::string>& hjbCustomOptionNames();

/// Their help, for `sltk hjb --help`.
extern const char* hjbCustomUsage;

/// True when the command line defines a custom problem (any of --fx --fy --fz).
bool hasHjbCustomProblem(const Options& opt);

/// Sets the custom problem on `solver`; returns "" or the usage error.
std::string setHjbCustomProblem(Options& opt, vtkCWENOHJBSolver* solver);

} // namespace sltkcli
