// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Q1.h
/// Multilinear (Q1) interpolation, thesis (4.28): the tensor product of 1D
/// linear interpolation on the 2^D nodes of the cell.

#include "sltk/interp/Interpolator.h"

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

} // namespace sltk
