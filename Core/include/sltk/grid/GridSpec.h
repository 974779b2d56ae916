// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file GridSpec.h
/// Geometry of a uniform node-centred grid in D = 1, 2, 3 dimensions
/// (thesis 3.2: x_i = x_0 + i dx, N nodes per axis including both ends).
///
/// Boundary policies per axis (thesis 3.5, Documentation/Numerics.md "Grids"):
///  - Extrapolate: ghost nodes filled by linear extrapolation; points outside
///    the domain are projected (clipped) onto it before interpolation;
///  - Periodic: N distinct nodes, dx = L / N, node N is node 0.

#include "sltk/core/AlwaysInline.h"
#include "sltk/core/Index.h"
#include "sltk/core/Status.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace sltk
{

enum class Boundary : std::uint8_t
{
  Extrapolate = 0,
  Periodic = 1
};

template <int D>
struct GridSpec
{
  static_assert(D >= 1 && D <= 3, "SLTK grids are 1D, 2D or 3D");
  static constexpr int Dim = D;

  std::array<Index, D> Dims{};      ///< nodes per axis (periodic: distinct nodes)
  std::array<double, D> Origin{};   ///< coordinates of node 0
  std::array<double, D> Spacing{};  ///< dx per axis, > 0
  std::array<Boundary, D> Bounds{}; ///< boundary policy per axis
  /// Index of node 0 in a larger grid of the same Origin and Spacing, when this
  /// grid is a window of it (a slab of a distributed solve): node i lies at
  /// Origin + (Offset + i) Spacing, bitwise where the larger grid has it.
  std::array<Index, D> Offset{};

  Index nodeCount() const
  {
    Index n = 1;
    for (int a = 0; a < D; ++a)
    {
      n *= this->Dims[a];
    }
    return n;
  }

  double coordinate(int axis, Index i) const
  {
    return this->Origin[axis] + static_cast<double>(i + this->Offset[axis]) * this->Spacing[axis];
  }

  /// The inverse of coordinate(): the fractional node index of x along an
  /// axis, in this grid's index (the larger grid's minus Offset; exact: an
  /// integer is subtracted).
  double indexCoordinate(int axis, double x) const
  {
    return (x - this->Origin[axis]) / this->Spacing[axis] - static_cast<double>(this->Offset[axis]);
  }

  /// Length of the domain along an axis: (N-1) dx, or N dx when periodic.
  double length(int axis) const
  {
    const Index cells = this->Bounds[axis] == Boundary::Periodic ? this->Dims[axis] : this->Dims[axis] - 1;
    return static_cast<double>(cells) * this->Spacing[axis];
  }

  /// Checks sizes and spacings; the message names the faulty axis and value.
  Status validate() const
  {
    static const char* names[3] = { "x", "y", "z" };
    for (int a = 0; a < D; ++a)
    {
      const Index minNodes = this->Bounds[a] == Boundary::Periodic ? 3 : 2;
      if (this->Dims[a] < minNodes)
      {
        return Status::invalidArgument("grid has " + std::to_string(this->Dims[a]) + " nodes along " + names[a] +
          "; at least " + std::to_string(minNodes) + " are needed");
      }
      if (!(this->Spacing[a] > 0.0) || !std::isfinite(this->Spacing[a]))
      {
        return Status::invalidArgument("grid spacing along " + std::string(names[a]) +
          " must be a positive finite number, got " + std::to_string(this->Spacing[a]));
      }
      if (!std::isfinite(this->Origin[a]))
      {
        return Status::invalidArgument(std::string("grid origin along ") + names[a] + " is not finite");
      }
    }
    return Status::ok();
  }
};

/// n nodes per axis on [lo, hi]^D (both ends included), one boundary policy.
template <int D>
inline GridSpec<D> uniformBox(Index n, double lo, double hi, Boundary boundary = Boundary::Extrapolate)
{
  GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    g.Dims[a] = n;
    g.Origin[a] = lo;
    g.Spacing[a] = (hi - lo) / static_cast<double>(n - 1);
    g.Bounds[a] = boundary;
  }
  return g;
}

/// Cell containing a point plus local coordinates in [0, 1] per axis. Left
/// unset until locate() fills it (`CellLocation<D>{}` gives zeros): the
/// interpolators keep small arrays of them in their inner loops, where zeroing
/// them took 5% of the CWENO cache's lookups (Documentation/Profile.md).
template <int D>
struct CellLocation
{
  std::array<Index, D> Cell;
  std::array<double, D> Local;
};

/// Locates the coordinate x along one axis: the cell index and the local
/// coordinate in [0, 1] of locate() below (the axes are independent, so a
/// grid-to-grid resampling can tabulate them once per axis).
template <int D>
SLTK_ALWAYS_INLINE void locateAxis(const GridSpec<D>& g, int a, double x, Index& cell, double& local)
{
  const double n = static_cast<double>(g.Dims[a]);
  double s = g.indexCoordinate(a, x);
  if (g.Bounds[a] == Boundary::Periodic)
  {
    s = s - n * std::floor(s / n);
    if (s >= n) // rounding of the wrap
    {
      s = 0.0;
    }
  }
  else
  {
    s = s < 0.0 ? 0.0 : (s > n - 1.0 ? n - 1.0 : s);
  }
  // The node nearest to s (s >= 0 here): floor(s + 0.5) snaps exactly where
  // nearbyint(s) would, since a tie lies 0.5 from both candidates.
  const double r = static_cast<double>(floorToIndex(s + 0.5));
  if (std::fabs(s - r) < 1e-10)
  {
    s = r;
  }
  const Index lastCell = g.Bounds[a] == Boundary::Periodic ? g.Dims[a] - 1 : g.Dims[a] - 2;
  Index c = floorToIndex(s);
  if (c > lastCell)
  {
    c = lastCell;
  }
  cell = c;
  local = s - static_cast<double>(c);
}

/// Locates x in the grid. Extrapolate axes clip x onto [x_0, x_{N-1}]
/// (feet outside the domain go to the boundary cell, thesis 3.5); periodic
/// axes wrap x into [x_0, x_0 + N dx). Exact at nodes: a point within
/// 1e-10 cells of a node gets that node's integer coordinate.
template <int D>
SLTK_ALWAYS_INLINE CellLocation<D> locate(const GridSpec<D>& g, const double* x)
{
  CellLocation<D> loc;
  for (int a = 0; a < D; ++a)
  {
    locateAxis(g, a, x[a], loc.Cell[a], loc.Local[a]);
  }
  return loc;
}

} // namespace sltk
