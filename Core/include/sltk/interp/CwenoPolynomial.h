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
/// All 1 + 2^D polynomials of a cell come from one table (stencilTable()): along
/// each axis, the four values (a, b, c, d) at t = -1, 0, 1, 2 give the seven 1D
/// coefficients of LineCoefficient, shared by the cubic Q and the parabolas P_L,
/// P_R of 3.3.1 (the inverse Vandermonde matrices printed by
/// bench/derive/derive_cweno.py, written with the second increments
/// e_L = a - 2b + c, e_R = b - 2c + d):
///   Q   = b + (c - b - e_L/2 - (e_R - e_L)/6) t + e_L/2 t^2 + (e_R - e_L)/6 t^3,
///   P_L = b + (c - b - e_L/2) t + e_L/2 t^2,       (t = -1, 0, 1)
///   P_R = b + (c - b - e_R/2) t + e_R/2 t^2.       (t = 0, 1, 2)
/// D-dimensional interpolation is their tensor product, so the coefficients of
/// every polynomial are entries of the 7^D tensor of the 1D coefficients.

#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"

#include <array>

namespace sltk
{
namespace cweno
{

using sltk::ipow;

/// The seven 1D coefficients of one line of the stencil (table entries along one axis).
enum LineCoefficient : int
{
  Value = 0,  ///< b: the t^0 coefficient of Q, P_L and P_R
  Cubic1 = 1, ///< the t coefficient of Q
  Second = 2, ///< e_L / 2: the t^2 coefficient of Q and of P_L
  Cubic3 = 3, ///< (e_R - e_L) / 6: the t^3 coefficient of Q
  Left1 = 4,  ///< the t coefficient of P_L
  Right1 = 5, ///< the t coefficient of P_R
  Right2 = 6, ///< e_R / 2: the t^2 coefficient of P_R
  LineCount = 7
};

/// Table entry of the coefficient of t^j, per polynomial: [0] Q, [1] P_L, [2] P_R.
constexpr int LineIndex[3][4] = {
  { Value, Cubic1, Second, Cubic3 },
  { Value, Left1, Second, -1 },
  { Value, Right1, Right2, -1 },
};

/// The seven coefficients of the line (a, b, c, d) at t = -1, 0, 1, 2, into
/// out[o * stride]. T is double or a SIMD vector of lanes (Lanes.h), each lane
/// with the same operations in the same order.
template <class T>
SLTK_LANES_INLINE void lineCoefficients(const T& a, const T& b, const T& c, const T& d, T* out, int stride)
{
  const T eL = a - 2.0 * b + c; // second increments of the two parabolas
  const T eR = b - 2.0 * c + d;
  const T jump = c - b;
  const T second = 0.5 * eL;
  const T cubic3 = (eR - eL) * (1.0 / 6.0);
  const T right2 = 0.5 * eR;
  const T left1 = jump - second;
  out[Value * stride] = b;
  out[Cubic1 * stride] = left1 - cubic3;
  out[Second * stride] = second;
  out[Cubic3 * stride] = cubic3;
  out[Left1 * stride] = left1;
  out[Right1 * stride] = jump - right2;
  out[Right2 * stride] = right2;
}

/// Size of the table of a D-dimensional stencil.
template <int D>
constexpr int TableSize = ipow(LineCount, D);

namespace detail
{
/// One axis of stencilTable(): the lines along axis A of a tensor whose axes
/// below A already hold the 7 coefficients and the others the 4 values.
template <int D, int A, class T>
SLTK_LANES_INLINE void tablePass(const T* in, T* out)
{
  constexpr int lower = ipow(LineCount, A); // stride of axis A
  constexpr int upper = ipow(4, D - 1 - A);
  for (int h = 0; h < upper; ++h)
  {
    const T* src = in + h * 4 * lower;
    T* dst = out + h * LineCount * lower;
    for (int l = 0; l < lower; ++l) // consecutive lines: vectorisable
    {
      lineCoefficients(src[l], src[l + lower], src[l + 2 * lower], src[l + 3 * lower], dst + l, lower);
    }
  }
}

template <int D, int A, class T>
SLTK_LANES_INLINE void tablePasses(const T* in, T* table)
{
  if constexpr (A == D - 1)
  {
    tablePass<D, A>(in, table);
  }
  else
  {
    T next[ipow(LineCount, A + 1) * ipow(4, D - 1 - A)];
    tablePass<D, A>(in, next);
    tablePasses<D, A + 1>(next, table);
  }
}
} // namespace detail

/// The 7^D tensor of 1D coefficients (LineCoefficient along each axis, x
/// fastest) of the 4^D stencil data u (x fastest, t = -1..2 per axis); T as
/// in lineCoefficients().
template <int D, class T>
SLTK_LANES_INLINE void stencilTable(const T* u, T* table)
{
  detail::tablePasses<D, 0>(u, table);
}

/// Table entries of the N^D coefficients of a polynomial whose axis a is
/// polynomial kind[a] of LineIndex (N = 4: the cubic on every axis, N = 3: parabolas).
template <int D, int N>
constexpr std::array<int, ipow(N, D)> tableIndices(const std::array<int, D>& kind)
{
  std::array<int, ipow(N, D)> index{};
  for (int p = 0; p < ipow(N, D); ++p)
  {
    int rest = p;
    int at = 0;
    for (int a = 0, stride = 1; a < D; ++a, stride *= LineCount)
    {
      at += LineIndex[kind[a]][rest % N] * stride;
      rest /= N;
    }
    index[p] = at;
  }
  return index;
}

/// Table entries of the optimal polynomial's 4^D coefficients (tensor cubic).
template <int D>
constexpr std::array<int, ipow(4, D)> optimalIndices()
{
  return tableIndices<D, 4>(std::array<int, D>{}); // kind 0: Q on every axis
}

/// Table entries of the 3^D coefficients of the low-degree polynomial of one
/// octant: the tensor quadratic on the 3^D sub-stencil whose nodes along axis a
/// are t = 0, 1, 2 (P_R) if bit a of `octant` is set (east / north / top) and
/// t = -1, 0, 1 (P_L) otherwise. 1D: octant 0 = P_L, 1 = P_R; 2D: 0 = sw, 1 = se, 2 = nw, 3 = ne.
template <int D>
constexpr std::array<int, ipow(3, D)> octantIndices(int octant)
{
  std::array<int, D> kind{};
  for (int a = 0; a < D; ++a)
  {
    kind[a] = 1 + ((octant >> a) & 1);
  }
  return tableIndices<D, 3>(kind);
}

/// Coefficients z (4^D) of the optimal polynomial: the tensor cubic (bicubic,
/// tricubic) interpolating the 4^D stencil data u.
template <int D>
inline void optimalCoefficients(const double* u, double* z)
{
  double table[TableSize<D>];
  stencilTable<D>(u, table);
  constexpr std::array<int, ipow(4, D)> index = optimalIndices<D>();
  for (int p = 0; p < ipow(4, D); ++p)
  {
    z[p] = table[index[p]];
  }
}

/// Coefficients z (3^D) of the low-degree polynomial of one octant (octantIndices()).
template <int D>
inline void octantCoefficients(const double* u, int octant, double* z)
{
  double table[TableSize<D>];
  stencilTable<D>(u, table);
  const std::array<int, ipow(3, D)> index = octantIndices<D>(octant);
  for (int q = 0; q < ipow(3, D); ++q)
  {
    z[q] = table[index[q]];
  }
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
