// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Q1.h
/// Multilinear (Q1) interpolation, thesis (4.28): the tensor product of 1D
/// linear interpolation on the 2^D nodes of the cell.

#include "sltk/interp/Interpolator.h"

#include <vector>

namespace sltk
{

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
    // Collapse one axis at a time: exact for multilinear data, no branching.
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

/// Q1Interpolator::eval at the centres t_a = (m_a + 1/2) / R of the R^D
/// subcells of a cell with corner values `corner`, into `out` (m_0 fastest),
/// bit for bit: the same collapses, axis 0 first, each made once for all the
/// subcells that share it (R^D + ... + R 2^(D-1) linear interpolations
/// instead of (2^D - 1) R^D). `scratch` is reused between calls.
template <int D>
void q1AtSubcellCentres(const double* corner, int R, std::vector<double>& scratch, std::vector<double>& out)
{
  const double inv = 1.0 / R;
  out.assign(corner, corner + (1 << D));
  Index prefixes = 1; // R^a subcell coordinates m_0 .. m_(a-1) collapsed so far
  for (int a = 0, width = 1 << D; a < D; ++a, width >>= 1, prefixes *= R)
  {
    const int half = width >> 1;
    scratch.resize(static_cast<size_t>(prefixes * R * half));
    for (int m = 0; m < R; ++m)
    {
      const double t = (m + 0.5) * inv;
      for (Index q = 0; q < prefixes; ++q)
      {
        const double* v = out.data() + q * width;
        double* to = scratch.data() + (q + prefixes * m) * half;
        for (int c = 0; c < half; ++c)
        {
          to[c] = v[2 * c] + t * (v[2 * c + 1] - v[2 * c]);
        }
      }
    }
    out.swap(scratch);
  }
}

} // namespace sltk
