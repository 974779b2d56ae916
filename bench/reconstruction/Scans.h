// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Scans.h
/// Real scans (thesis 4.5.5, Tables 4.6-4.9): energies and Err_P converted to
/// the unit box of 4.5 (scale s = half the largest bounding-box extent:
/// Err_P / s, E_2 / s^((d+1)/2), the library's own conversion in Reconstruction.cxx).

#include "common/ThesisTables.h"
#include "reconstruction/Options.h"

#include "sltk/recon/Reconstruction.h"

#include <string>
#include <vector>

namespace sltkbench
{

struct ScanCase
{
  std::string Name;
  std::string File;     ///< relative to --data
  std::string TableKey; ///< "" when the thesis has no per-run table
  std::string GridKey;  ///< key of table_4_8_grids
  double Cdx = 1.0;
  double Kp = 2.0;
  sltk::InitialGuess Guess = sltk::InitialGuess::OutsideMarking;
  int MaxIterations = 100;
  std::string Note;
};

/// Reads the scan (x y z per line) and prints its table, one block per interpolator.
void runScan(const ScanCase& c, const std::vector<std::string>& interps, const ReconstructionBenchOptions& args,
  const ThesisTables& thesis, const sltk::Context& ctx);

} // namespace sltkbench
