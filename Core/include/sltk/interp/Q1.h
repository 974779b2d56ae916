// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Q1.h
/// Multilinear (Q1) interpolation, thesis (4.28): the tensor product of 1D
/// linear interpolation on the 2^D nodes of the cell.

#include "sltk/exec/Context.h"
#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"

#include <algorithm>
#include <type_traits>
#include <utility>
#include <vector>

namespace sltk
{

/// (4.28) from the 2^D corner values v of a cell (corner c: bit a of c is the
/// offset along axis a) at local coordinates t: one axis collapsed at a time,
/// axis 0 first (exact for multilinear data, no branching). Overwrites v.
template <int D>
inline double q1Collapse(double* v, const std::array<double, D>& t)
{
  int n = 1 << D;
  for (int a = 0; a < D; ++a)
  {
    n >>= 1;
    for (int c = 0; c < n; ++c)
    {
      v[c] = v[2 * c] + t[a] * (v[2 * c + 1] - v[2 * c]);
    }
  }
  return v[0];
}

template <int D>
class Q1Interpolator
{
public:
  static constexpr int Dim = D;
  static constexpr int GhostWidth = 1;

  explicit Q1Interpolator(const GridField<D, double>& field)
    : Corner(field, 0) // corner c: bit a of c is the offset along axis a
  {
  }

  /// Caches the 2^D corner values of the cell.
  void prepare(const std::array<Index, D>& cell) { this->Corner.prepare(cell); }
  void prepareIfNeeded(const std::array<Index, D>& cell) { this->Corner.prepareIfNeeded(cell); }

  /// (4.28): sum over corners of value * prod_a (t_a or 1 - t_a).
  double eval(const std::array<double, D>& t) const
  {
    double v[1 << D];
    for (int c = 0; c < (1 << D); ++c)
    {
      v[c] = this->Corner[c];
    }
    return q1Collapse<D>(v, t);
  }

private:
  StencilCache<D, 2> Corner;
};

/// The 2^D corner values of the cell with lowest corner `cell` (corner c: bit
/// a of c is the offset along axis a, Q1Interpolator's order).
template <int D>
void cellCorners(const GridField<D, double>& field, const std::array<Index, D>& cell, double* corner)
{
  const double* p = field.pointer(cell);
  for (int c = 0; c < (1 << D); ++c)
  {
    Index o = 0;
    for (int a = 0; a < D; ++a)
    {
      o += ((c >> a) & 1) * field.strides()[a];
    }
    corner[c] = p[o];
  }
}

/// The doubles each buffer of q1AtSubcellCentres holds: max(R^D, 2^D).
template <int D>
constexpr int q1SubcellBuffer(int R)
{
  return ipow(R, D) > (1 << D) ? ipow(R, D) : (1 << D);
}

/// One axis of q1AtSubcellCentres: the `prefixes` groups of `width` values in
/// `from` collapsed at the R centres of the axis into `to` (distinct buffers).
template <class Refinement>
SLTK_LANES_INLINE void q1SubcellPass(
  const double* from, double* to, int width, Index prefixes, Refinement R, double inv)
{
  const int half = width >> 1;
  for (int m = 0; m < static_cast<int>(R); ++m)
  {
    const double t = (m + 0.5) * inv;
    for (Index q = 0; q < prefixes; ++q)
    {
      const double* v = from + q * width;
      double* w = to + (q + prefixes * m) * half;
      for (int c = 0; c < half; ++c)
      {
        w[c] = v[2 * c] + t * (v[2 * c + 1] - v[2 * c]);
      }
    }
  }
}

/// Q1Interpolator::eval at the centres t_a = (m_a + 1/2) / R of the R^D
/// subcells of a cell with corner values `corner` (m_0 fastest), bit for bit:
/// the same collapses, axis 0 first, each made once for all the subcells that
/// share it (R^D + ... + R 2^(D-1) linear interpolations instead of
/// (2^D - 1) R^D). `first` and `second` hold q1SubcellBuffer<D>(R) doubles
/// each; returns the one that holds the values. R is an int, or a
/// std::integral_constant for a refinement known when compiling (the passes
/// then have fixed trip counts, which the compiler unrolls and vectorises).
template <int D, class Refinement>
const double* q1AtSubcellCentres(const double* corner, Refinement R, double* first, double* second)
{
  const double inv = 1.0 / static_cast<int>(R);
  std::copy(corner, corner + (1 << D), first);
  double* from = first;
  double* to = second;
  Index prefixes = 1; // R^a subcell coordinates m_0 .. m_(a-1) collapsed so far
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC unroll 3
#endif
  for (int a = 0, width = 1 << D; a < D; ++a, width >>= 1, prefixes *= static_cast<int>(R))
  {
    q1SubcellPass(from, to, width, prefixes, R, inv);
    std::swap(from, to);
  }
  return from;
}

/// `from` interpolated by (4.28) at the nodes of `to`'s grid on the x lines
/// [firstLine, endLine) (line l holds the nodes l N_0 .. l N_0 + N_0 - 1), bit
/// for bit interpolate(Q1Interpolator(from), from.spec(), x) node by node. The
/// cell and local coordinate along an axis depend on the node's index along
/// that axis only (locateAxis), so they are tabulated once per axis rather
/// than located per node (a division, a floor and a rounding per axis): the
/// transfer of phi and d between runs visits every node of the finer grid.
template <int D>
void q1Resample(
  const GridField<D, double>& from, Index firstLine, Index endLine, const Context& ctx, GridField<D, double>& to)
{
  const GridSpec<D>& g = to.spec();
  std::array<std::vector<Index>, D> cell;
  std::array<std::vector<double>, D> local;
  for (int a = 0; a < D; ++a)
  {
    cell[a].resize(static_cast<size_t>(g.Dims[a]));
    local[a].resize(static_cast<size_t>(g.Dims[a]));
    for (Index i = 0; i < g.Dims[a]; ++i)
    {
      locateAxis(from.spec(), a, g.coordinate(a, i), cell[a][static_cast<size_t>(i)], local[a][static_cast<size_t>(i)]);
    }
  }
  const Index nx = g.Dims[0], sx = to.strides()[0];
  ctx.parallelFor(firstLine, endLine,
    [&](Index b, Index e)
    {
      std::array<Index, D> c{};
      std::array<double, D> t{};
      double corner[1 << D];
      for (Index l = b; l < e; ++l)
      {
        const std::array<Index, D> i = to.nodeIndex(l * nx);
        for (int a = 1; a < D; ++a)
        {
          c[a] = cell[a][static_cast<size_t>(i[a])];
          t[a] = local[a][static_cast<size_t>(i[a])];
        }
        double* out = to.pointer(i);
        for (Index x = 0; x < nx; ++x)
        {
          c[0] = cell[0][static_cast<size_t>(x)];
          t[0] = local[0][static_cast<size_t>(x)];
          cellCorners<D>(from, c, corner);
          out[x * sx] = q1Collapse<D>(corner, t);
        }
      }
    });
}

} // namespace sltk
