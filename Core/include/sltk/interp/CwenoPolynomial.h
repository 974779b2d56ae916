// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CwenoPolynomial.h
/// Tensor-product interpolating polynomials of the CWENO reconstruction
/// (thesis 3.3.1-3.3.2 and its 3D extension), in local coordinates
/// t_a = (x_a - x_{i_a}) / h_a: the cell has its nodes at t = 0 and 1, the
/// stencil at t = -1, 0, 1, 2. A polynomial of degree N-1 per axis is stored as
/// its N^D monomial coefficients c[j_0 + N j_1 + N^2 j_2] of t_0^j_0 t_1^j_1 t_2^j_2
/// (x fastest, like GridField and the data vector U of (3.26)).
///
/// The 1D matrices are the inverse Vandermonde matrices printed by
/// bench/derive/derive_cweno.py; D-dimensional interpolation is their tensor product.

#include "sltk/interp/Interpolator.h"

#include <array>

namespace sltk
{
namespace cweno
{

using sltk::ipow;

/// Data -> coefficient matrices of 1D interpolation (rows: coefficient of t^j,
/// columns: data in increasing t).
struct Stencil1D
{
  /// Cubic Q of 3.3.1 on t = -1, 0, 1, 2.
  static constexpr double Cubic[4][4] = {
    { 0.0, 1.0, 0.0, 0.0 },
    { -1.0 / 3.0, -0.5, 1.0, -1.0 / 6.0 },
    { 0.5, -1.0, 0.5, 0.0 },
    { -1.0 / 6.0, 0.5, -0.5, 1.0 / 6.0 },
  };
  /// Parabolas of 3.3.1: [0] P_L on t = -1, 0, 1 (low side), [1] P_R on t = 0, 1, 2 (high side).
  static constexpr double Quadratic[2][3][3] = {
    {
      { 0.0, 1.0, 0.0 },
      { -0.5, 0.0, 0.5 },
      { 0.5, -1.0, 0.5 },
    },
    {
      { 1.0, 0.0, 0.0 },
      { -1.5, 2.0, -0.5 },
      { 0.5, -1.0, 0.5 },
    },
  };
};

/// In place: replaces every line of an N^D tensor (x fastest) along axis a by Mat[a] * line,
/// for all axes; Mat[a] points to an N x N row-major matrix.
template <int D, int N>
inline void transformAlongAxes(double* v, const double* const (&mat)[D])
{
  constexpr int size = ipow(N, D);
  int stride = 1;
  for (int a = 0; a < D; ++a)
  {
    const double* m = mat[a];
    for (int outer = 0; outer < size; outer += stride * N)
    {
      for (int inner = 0; inner < stride; ++inner)
      {
        double* line = v + outer + inner;
        double in[N];
        for (int k = 0; k < N; ++k)
        {
          in[k] = line[k * stride];
        }
        for (int j = 0; j < N; ++j)
        {
          double s = 0.0;
          for (int k = 0; k < N; ++k)
          {
            s += m[j * N + k] * in[k];
          }
          line[j * stride] = s;
        }
      }
    }
    stride *= N;
  }
}

/// Coefficients z (4^D) of the optimal polynomial: the tensor cubic (bicubic,
/// tricubic) interpolating the 4^D stencil data u (x fastest, t = -1..2 per axis).
template <int D>
inline void optimalCoefficients(const double* u, double* z)
{
  for (int p = 0; p < ipow(4, D); ++p)
  {
    z[p] = u[p];
  }
  const double* mats[D];
  for (int a = 0; a < D; ++a)
  {
    mats[a] = &Stencil1D::Cubic[0][0];
  }
  transformAlongAxes<D, 4>(z, mats);
}

/// Coefficients z (3^D) of the low-degree polynomial of one octant: the tensor
/// quadratic interpolating the 3^D sub-stencil whose nodes along axis a are
/// t = 0, 1, 2 if bit a of `octant` is set (east / north / top) and t = -1, 0, 1
/// otherwise. 1D: octant 0 = P_L, 1 = P_R; 2D: 0 = sw, 1 = se, 2 = nw, 3 = ne.
template <int D>
inline void octantCoefficients(const double* u, int octant, double* z)
{
  for (int q = 0; q < ipow(3, D); ++q)
  {
    int rest = q;
    int src = 0;
    for (int a = 0, stride = 1; a < D; ++a, stride *= 4)
    {
      src += (rest % 3 + ((octant >> a) & 1)) * stride;
      rest /= 3;
    }
    z[q] = u[src];
  }
  const double* mats[D];
  for (int a = 0; a < D; ++a)
  {
    mats[a] = &Stencil1D::Quadratic[(octant >> a) & 1][0][0];
  }
  transformAlongAxes<D, 3>(z, mats);
}

/// Index in the 4^D layout of coefficient q of the 3^D layout (same monomial).
template <int D>
constexpr int quadraticToCubicIndex(int q)
{
  int p = 0;
  for (int a = 0, stride = 1; a < D; ++a, stride *= 4)
  {
    p += (q % 3) * stride;
    q /= 3;
  }
  return p;
}

/// Horner evaluation of the tensor polynomial with N^D coefficients c at t,
/// collapsing x first, then y, then z.
template <int D, int N>
inline double evalTensor(const double* c, const std::array<double, D>& t)
{
  constexpr int size = ipow(N, D);
  double v[size / N];
  int n = size / N;
  for (int g = 0; g < n; ++g)
  {
    const double* cg = c + g * N;
    double s = cg[N - 1];
    for (int j = N - 2; j >= 0; --j)
    {
      s = s * t[0] + cg[j];
    }
    v[g] = s;
  }
  for (int a = 1; a < D; ++a)
  {
    n /= N;
    for (int g = 0; g < n; ++g)
    {
      const double* vg = v + g * N;
      double s = vg[N - 1];
      for (int j = N - 2; j >= 0; --j)
      {
        s = s * t[a] + vg[j];
      }
      v[g] = s;
    }
  }
  return v[0];
}

} // namespace cweno
} // namespace sltk
