// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PresetRun.h
/// The thesis's HJB tests (Presets.h) as run-time choices, for the VTK filter
/// and the CLI: choose a test, N, the interpolator and optionally the final
/// time and Courant number; makePresetSolver() (HjbSolver.h) builds the solver
/// (for Test 5 it also keeps the first time each node is reached (3.40)).

#include "sltk/core/Index.h"
#include "sltk/core/Status.h"
#include "sltk/hjb/HjbResult.h"
#include "sltk/interp/InterpolatorKind.h"

namespace sltk
{

enum class HjbPreset : int
{
  Test1Rotation = 1,    ///< 3.5.1, 2D, pure transport
  Test2SemiConcave = 2, ///< 3.5.2, 1D
  Test3Eikonal = 3,     ///< 3.5.3, 1D periodic, per-stage controls
  Test4Quadratic = 4,   ///< 3.5.4, 2D
  Test5Zermelo = 5      ///< 3.5.5, 2D with obstacles, reachable set
<<<<<<< HEAD
};

/// Grid of a preset as three axes (unused axes: one node).
struct HjbGrid
{
  int Dimension = 2;
  std::array<long long, 3> Dims{ 1, 1, 1 };
  std::array<double, 3> Origin{ 0.0, 0.0, 0.0 };
  std::array<double, 3> Spacing{ 1.0, 1.0, 1.0 };
=======
>>>>>>> hjbtidy
};

struct PresetRunOptions
{
  HjbPreset Preset = HjbPreset::Test1Rotation;
  Index Nodes = 81;            ///< N per direction (Test 3: distinct periodic nodes)
  double FinalTime = -1.0;     ///< < 0: the preset's
  double CourantNumber = -1.0; ///< dt = lambda dx; <= 0: the preset's
  InterpolatorKind Interpolator = InterpolatorKind::CwenoZ;
};

<<<<<<< HEAD
struct HjbRunResult
{
  HjbGrid Grid;
  std::vector<double> Value;     ///< u at T, x fastest
  std::vector<double> ReachTime; ///< Test 5: first t_k with u <= 0 (+inf: never); else empty
  double FinalTime = 0.0;
  double L1Error = std::numeric_limits<double>::quiet_NaN(); ///< when an exact solution is known
  double LinfError = std::numeric_limits<double>::quiet_NaN();
  Index Steps = 0;
  double EvaluationsPerNode = 0.0;
};

=======
>>>>>>> hjbtidy
/// The grid a preset uses for N nodes (checks N).
Status presetGrid(HjbPreset preset, Index nodes, HjbGrid& grid);

} // namespace sltk
