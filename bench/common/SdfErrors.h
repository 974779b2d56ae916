// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SdfErrors.h
/// L1 errors of a level-set function against the exact signed distance
/// (4.5.1; the text gives no formula), shared by the benchmarks of the uniform
/// and the tiled reconstruction: over all nodes against the distance cut at
/// +-gamma (1.49)/(1.51), and over the band |exact| < gamma.

#include "sltk/grid/GridSpec.h"
#include "sltk/recon/UnitBox.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace sltkbench
{

/// {L1 against the cut distance, L1 over the band}. `phi(i)` gives node i's
/// value on grid `g`, and `gamma` the cut-off, both in the units `box` maps to
/// the user's (the reconstruction's unit box; the default box is the identity,
/// for a result already in the user's units), where `exact(x)` and the errors are.
template <int D, class Phi, class Exact>
std::pair<double, double> l1Errors(
  const sltk::GridSpec<D>& g, const Phi& phi, const Exact& exact, double gamma, const sltk::UnitBox<D>& box = {})
{
  const double scale = box.Scale, cut = gamma * scale;
  double cell = 1.0;
  for (int a = 0; a < D; ++a)
  {
    cell *= g.Spacing[a] * scale;
  }
  double all = 0.0, band = 0.0;
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    std::array<sltk::Index, D> i{};
    std::array<double, D> x{};
    sltk::Index rest = k;
    for (int a = 0; a < D; ++a)
    {
      i[a] = rest % g.Dims[a];
      rest /= g.Dims[a];
      x[a] = box.Centre[a] + scale * g.coordinate(a, i[a]);
    }
    const double e = exact(x);
    const double v = scale * phi(i);
    all += std::fabs(v - std::max(-cut, std::min(cut, e)));
    if (std::fabs(e) < cut)
    {
      band += std::fabs(v - e);
    }
  }
  return { all * cell, band * cell };
}

} // namespace sltkbench
