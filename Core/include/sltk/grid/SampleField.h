// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SampleField.h
/// Nodal sampling of a function on a grid: f(x) at every node, then the ghost
/// layers from the boundary policy (or f itself on the ghosts, for tests and
/// exact boundary data).

#include "sltk/grid/GridField.h"

namespace sltk
{

enum class GhostFill
{
  Boundary, ///< fillGhosts(): the grid's boundary policy
  Exact     ///< f evaluated at the ghost nodes too
};

/// A field with `ghost` layers holding f(x) at the nodes; f takes `const double* x`
/// (three coordinates, those beyond D are zero, so one f serves 1D, 2D and 3D). Runs serially: initial data, tests and small setups.
template <int D, class F>
GridField<D> sampleField(const GridSpec<D>& spec, int ghost, F&& f, GhostFill fill = GhostFill::Boundary)
{
  GridField<D> u(spec, ghost);
  const int pad = fill == GhostFill::Exact ? ghost : 0;
  std::array<Index, D> ext{};
  Index total = 1;
  for (int a = 0; a < D; ++a)
  {
    ext[a] = spec.Dims[a] + 2 * pad;
    total *= ext[a];
  }
  for (Index k = 0; k < total; ++k)
  {
    std::array<Index, D> i{};
    double x[3] = { 0.0, 0.0, 0.0 };
    Index rest = k;
    for (int a = 0; a < D; ++a)
    {
      i[a] = rest % ext[a] - pad;
      rest /= ext[a];
      x[a] = spec.coordinate(a, i[a]);
    }
    u(i) = f(static_cast<const double*>(x));
  }
  if (fill == GhostFill::Boundary)
  {
    u.fillGhosts();
  }
  return u;
}

} // namespace sltk
