// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbCustomProblem.h
/// `sltk hjb` options of a problem given by formulas (vtkCWENOHJBSolver's
/// Custom preset): their parser, their help, and setting them on the filter.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

class vtkCWENOHJBSolver;

namespace sltkcli
{

/// A problem given by formulas, as the command line gives it.
struct HjbCustomProblem
{
  /// The help group of its options, and their preamble (the equation and the formula syntax).
  static const char* const Group;
  static const char* const Help;

  std::string Dynamics[3] = { "0", "0", "0" };
  std::string Cost, InitialValue, Obstacle, Exact;
  std::string Argmin[3];
  std::vector<double> Nodes = { 81, 81 };
  std::vector<double> Domain;
  std::string Periodic;
  int ControlSet = 0; ///< none, box, ball, sphere
  int ControlDimension = 1;
  std::vector<double> Lower = { -1, -1, -1 };
  std::vector<double> Upper = { 1, 1, 1 };
  std::vector<double> Center = { 0, 0, 0 };
  double Radius = 1.0;
  int RKOrder = 3;
  int Tabulation = 33;
  int WarmStart = 0;
  double Tolerance = 1e-8;
  bool Reach = false;
  bool ControlPerStep = false; ///< PerStageControls off: one control per time step

  /// Adds its options to `app`, in the help group Group.
  void addOptions(CLI::App* app);

  /// Sets the problem on `solver`; returns "" or the usage error.
  std::string apply(vtkCWENOHJBSolver* solver) const;
};

} // namespace sltkcli
