// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Synthetic.h
/// Tables 4.2-4.5 (thesis 4.5.3, 4.5.4) and the noisy figures 4.8, 4.11: a
/// synthetic cloud with a known exact signed distance, reconstructed with
/// Runs = 1..R, each run's phi compared with the exact SDF (L1, 4.5.1).

#include "common/ThesisTables.h"
#include "reconstruction/Options.h"

#include "sltk/recon/Reconstruction.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace sltkbench
{

template <int D>
struct SyntheticCase
{
  std::string Name;
  std::string TableKey; ///< "" when the thesis has no table for the case
  std::string Title;
  sltk::PointCloud<D> Cloud;
  std::function<double(const std::array<double, D>&)> Exact; ///< exact signed distance
  int Runs = 3;
  double SurfaceEnergy = std::nan(""); ///< E_2 of the exact shape, when computed
};

/// Prints the case's table, one block per interpolator. `schedule` empty: Table 4.1.
template <int D>
void runSynthetic(const SyntheticCase<D>& c, const std::vector<std::string>& interps,
  const ReconstructionBenchOptions& args, const ThesisTables& thesis, const sltk::Context& ctx,
  const std::vector<sltk::RunParameters>& schedule = {});

extern template void runSynthetic<2>(const SyntheticCase<2>&, const std::vector<std::string>&,
  const ReconstructionBenchOptions&, const ThesisTables&, const sltk::Context&,
  const std::vector<sltk::RunParameters>&);
extern template void runSynthetic<3>(const SyntheticCase<3>&, const std::vector<std::string>&,
  const ReconstructionBenchOptions&, const ThesisTables&, const sltk::Context&,
  const std::vector<sltk::RunParameters>&);

} // namespace sltkbench
