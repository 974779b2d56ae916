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
};

struct PresetRunOptions
{
  HjbPreset Preset = HjbPreset::Test1Rotation;
  Index Nodes = 81;            ///< N per direction (Test 3: distinct periodic nodes)
  double FinalTime = -1.0;     ///< < 0: the preset's
  double CourantNumber = -1.0; ///< dt = lambda dx; <= 0: the preset's
  InterpolatorKind Interpolator = InterpolatorKind::CwenoZ;
};

/// The grid a preset uses for N nodes (checks N).
Status presetGrid(HjbPreset preset, Index nodes, HjbGrid& grid);

} // namespace sltk
