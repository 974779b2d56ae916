// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Options.h
/// The reconstruction benchmark's options (see the usage in
/// bench/BenchReconstruction.cxx) and its interpolator names.

#include "sltk/interp/InterpolatorKind.h"
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
  std::string Tables = "/work/shared/reference/thesis_tables.json";
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

/// The interpolator of a benchmark name (a registry name, InterpolatorKind.h, or
/// "weno" for weno3) and its column key in thesis_tables.json ("Q1", "WENO"; ""
/// for the CWENO family, which the thesis's chapter 4 does not use). False for
/// an unknown name.
inline bool interpolatorOf(const std::string& name, sltk::InterpolatorKind& kind, std::string& thesisKey)
{
  if (!sltk::parseInterpolator(name == "weno" ? "weno3" : name, kind))
  {
    return false;
  }
  thesisKey = kind == sltk::InterpolatorKind::Q1 ? "Q1" : kind == sltk::InterpolatorKind::Weno3 ? "WENO" : "";
  return true;
}

/// Sets options.Interpolator and the thesis key from a benchmark name; prints
/// "unknown interpolator NAME" and returns false for an unknown name.
inline bool selectInterpolator(const std::string& name, sltk::ReconstructionOptions& options, std::string& thesisKey)
{
  if (!interpolatorOf(name, options.Interpolator, thesisKey))
  {
    std::printf("unknown interpolator %s\n", name.c_str());
    return false;
  }
  return true;
}

} // namespace sltkbench
