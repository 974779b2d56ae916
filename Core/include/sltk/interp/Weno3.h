// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Weno3.h
/// Third-order WENO interpolation from point values, thesis 2.3.4
/// (2.65)-(2.76), in D = 1, 2, 3 dimensions by dimensional splitting.
///
/// Splitting order (thesis 2.3.4, two-dimensional case): "four 1D WENO
/// interpolations in the y direction" on the columns x_{i-1}, ..., x_{i+2} at
/// the target y, then one in x on those four values; 3D "analogously":
/// 16 interpolations along z, then 4 along y, then 1 along x. In general the
/// last axis is interpolated first and x last.
///
/// prepare() only caches the 4^D stencil values: the linear weights (2.76)
/// depend on the evaluation point, hence so do the nonlinear weights (2.68),
/// and all the work happens in eval() (the contrast with CWENO, Remarks 3.1-3.2).

#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Weno3Kernel1D.h"

#include <cassert>

namespace sltk
{

template <int D>
class Weno3Interpolator
{
public:
  static constexpr int Dim = D;
  static constexpr int GhostWidth = 2;

  explicit Weno3Interpolator(const GridField<D, double>& field)
    : Stencil(field, -1) // stencil digit 0..3 is node -1..2 along each axis
  {
    assert(field.ghost() >= GhostWidth);
    for (int a = 0; a < D; ++a)
    {
      const double dx = field.spec().Spacing[a];
      this->Eps[a] = dx * dx; // epsilon = dx^2 (2.67), per axis
    }
  }

  /// Caches the 4^D stencil values of the cell (nodes -1..2 along each axis).
  void prepare(const std::array<Index, D>& cell) { this->Stencil.prepare(cell); }
  void prepareIfNeeded(const std::array<Index, D>& cell) { this->Stencil.prepareIfNeeded(cell); }

  /// Dimension-split WENO3 at local coordinates t in [0, 1]^D: each pass
  /// applies the 1D reconstruction (2.69) along one axis, last axis first.
  double eval(const std::array<double, D>& t) const
  {
    // First pass along axis D-1, from the cache into 4^(D-1) line values.
    constexpr int n0 = StencilSize / 4;
    double v[n0];
    for (int c = 0; c < n0; ++c)
    {
      v[c] = weno3Interpolate1D(this->Stencil[c], this->Stencil[c + n0], this->Stencil[c + 2 * n0],
        this->Stencil[c + 3 * n0], t[D - 1], this->Eps[D - 1]);
    }
    // Remaining axes, down to x: the values of axis a sit at stride 4^a.
    int n = n0;
    for (int a = D - 2; a >= 0; --a)
    {
      n /= 4;
      for (int c = 0; c < n; ++c)
      {
        v[c] = weno3Interpolate1D(v[c], v[c + n], v[c + 2 * n], v[c + 3 * n], t[a], this->Eps[a]);
      }
    }
    return v[0];
  }

private:
  static constexpr int StencilSize = StencilCache<D, 4>::Size;

  StencilCache<D, 4> Stencil;
  double Eps[D] = {};
};

} // namespace sltk
