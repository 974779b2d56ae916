// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Options.h
/// The reconstruction benchmark's options (see the usage in
/// bench/BenchReconstruction.cxx) and its interpolator names.

#include "common/ThesisNames.h"
#include "common/ThesisTables.h"
#include "sltk/recon/Reconstruction.h"

#include <cstdio>

#include <cmath>
#include <string>
#include <vector>

namespace sltkbench
{

struct ReconstructionBenchOptions
{
  std::vector<std::string> Cases;
  std::vector<std::string> Interps;
  int Threads = 1;
  std::string Tables = DefaultThesisTablesPath;
  std::string Data = "/work/shared/data/clouds";
  bool Scans = false;
  double Cdx = std::nan("");
  double Kp = std::nan("");
  int Runs = 0;
  bool Log = false;
  double Tolerance = std::nan(""); ///< threshold of (4.33); NaN: the library's 1e-4
  bool FinalOnly = false;          ///< synthetic cases: one R-run call, L1 of run R only
  double Noise = 0.1;              ///< sigma of the noisy cases: "10% noise" on the unit circle / sphere
  int Padding = -1;                ///< cells of padding per side; < 0: the library's default
};

/// The interpolator of a benchmark name (ThesisNames.h: a registry name or
/// "weno" for weno3) and its column key in thesis_tables.json ("Q1", "WENO";
/// chapter 4's tables have no CWENO columns, so the CWENO family finds no
/// thesis value). False for an unknown name.
inline bool interpolatorOf(const std::string& name, sltk::InterpolatorKind& kind, std::string& key)
{
  if (!parseBenchInterpolator(name, kind))
  {
    return false;
  }
  key = thesisKey(kind);
  return true;
}

/// Sets options.Interpolator and the thesis key from a benchmark name; prints
/// "unknown interpolator NAME" and returns false for an unknown name.
inline bool selectInterpolator(const std::string& name, sltk::ReconstructionOptions& options, std::string& thesisKey)
{
  sltk::InterpolatorKind kind{};
  const bool known = interpolatorOf(name, kind, thesisKey);
  options.Interpolator = kind;
  if (!known)
  {
    std::printf("unknown interpolator %s\n", name.c_str());
    return false;
  }
  return true;
}

} // namespace sltkbench
