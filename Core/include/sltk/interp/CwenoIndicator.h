// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CwenoIndicator.h
/// Oscillation indicators of the CWENO reconstruction as quadratic forms of the
/// tensor monomial coefficients (CwenoPolynomial.h):
///
///   OSC[P] = sum_{|alpha| >= 2} Delta^(2|alpha| - 2 - D) int_cell (d^alpha P)^2 dV,
///
/// which is (3.18) for D = 1 (Delta = dx) and (3.24) for D = 2 (Delta = the cell
/// diameter, integral over the cell in dx dy: Documentation/Numerics.md), and the same scaling in
/// 3D: the exponent keeps OSC ~ 1 across a kink and OSC = O(h^2) on smooth data
/// (a kink makes d^alpha P ~ h^(1-|alpha|), the cell has volume h^D).
///
/// With P = sum_j z_j prod_a t_a^(j_a), t_a = (x_a - x_{i_a}) / h_a, the form is
/// OSC = z^T M z with (the 1D integrals factorise)
///   M_jk = sum_alpha c_alpha prod_a I^(alpha_a)_(j_a k_a),
///   c_alpha = Delta^(2|alpha| - 2 - D) prod_a h_a^(1 - 2 alpha_a),
///   I^a_jk = int_0^1 (d^a t^j)(d^a t^k) dt = j!/(j-a)! k!/(k-a)! / (j + k - 2a + 1).
/// On a uniform grid M = M_ref / dx^2: the matrix M of (3.25), printed in the
/// Appendix and by bench/derive/derive_cweno.py.

#include "sltk/interp/CwenoPolynomial.h"

#include <cmath>
#include <vector>

namespace sltk
{
namespace cweno
{

/// I^a_jk = int_0^1 (d^a t^j / dt^a)(d^a t^k / dt^a) dt.
inline double derivativeIntegral(int a, int j, int k)
{
  if (j < a || k < a)
  {
    return 0.0;
  }
  double fj = 1.0;
  double fk = 1.0;
  for (int m = 0; m < a; ++m)
  {
    fj *= static_cast<double>(j - m);
    fk *= static_cast<double>(k - m);
  }
  return fj * fk / static_cast<double>(j + k - 2 * a + 1);
}

/// The quadratic form OSC = z^T M z of polynomials with N coefficients per axis
/// (N = 4: the optimal polynomial, N = 3: the octant polynomials), for the given
/// spacings and scaling length Delta. Built once per interpolator.
template <int D, int N>
class IndicatorForm
{
public:
  static constexpr int Size = ipow(N, D);

  IndicatorForm(const std::array<double, D>& spacing, double delta)
    : Matrix(static_cast<size_t>(Size) * Size, 0.0)
  {
    // c_alpha for every multi-index alpha with alpha_a <= N - 1 (alpha laid out like j).
    double weight[Size];
    for (int al = 0; al < Size; ++al)
    {
      int rest = al;
      int order = 0;
      double c = 1.0;
      for (int a = 0; a < D; ++a)
      {
        const int alpha = rest % N;
        rest /= N;
        order += alpha;
        c *= std::pow(spacing[a], 1 - 2 * alpha);
      }
      weight[al] = order >= 2 ? c * std::pow(delta, 2 * order - 2 - D) : 0.0;
    }
    double integral[N][N][N];
    for (int a = 0; a < N; ++a)
    {
      for (int j = 0; j < N; ++j)
      {
        for (int k = 0; k < N; ++k)
        {
          integral[a][j][k] = derivativeIntegral(a, j, k);
        }
      }
    }
    for (int p = 0; p < Size; ++p)
    {
      for (int q = 0; q < Size; ++q)
      {
        double m = 0.0;
        for (int al = 0; al < Size; ++al)
        {
          if (weight[al] == 0.0)
          {
            continue;
          }
          double term = weight[al];
          int rp = p;
          int rq = q;
          int ra = al;
          for (int a = 0; a < D; ++a)
          {
            term *= integral[ra % N][rp % N][rq % N];
            rp /= N;
            rq /= N;
            ra /= N;
          }
          m += term;
        }
        this->Matrix[static_cast<size_t>(p) * Size + q] = m;
      }
    }
    this->pack();
  }

  /// OSC[P] = z^T M z for the coefficients z (Size values).
  double operator()(const double* z) const
  {
    // Upper triangle of the active rows (monomials of total degree >= 2; the others
    // have no derivative of order >= 2), off-diagonal entries doubled: about 40% of
    // the dense cost in 3D.
    double y[Size];
    for (int i = 0; i < this->ActiveCount; ++i)
    {
      y[i] = z[this->Active[i]];
    }
    const double* m = this->Packed.data();
    double s = 0.0;
    for (int i = 0; i < this->ActiveCount; ++i)
    {
      double row = 0.0;
      for (int j = i; j < this->ActiveCount; ++j)
      {
        row += *m++ * y[j];
      }
      s += y[i] * row;
    }
    return s;
  }

  /// M_pq (for tests and for printing the Appendix matrices).
  double entry(int p, int q) const { return this->Matrix[static_cast<size_t>(p) * Size + q]; }

private:
  void pack()
  {
    this->ActiveCount = 0;
    for (int p = 0; p < Size; ++p)
    {
      bool active = false;
      for (int q = 0; q < Size; ++q)
      {
        active = active || this->entry(p, q) != 0.0;
      }
      if (active)
      {
        this->Active[this->ActiveCount++] = p;
      }
    }
    this->Packed.clear();
    for (int i = 0; i < this->ActiveCount; ++i)
    {
      for (int j = i; j < this->ActiveCount; ++j)
      {
        this->Packed.push_back((i == j ? 1.0 : 2.0) * this->entry(this->Active[i], this->Active[j]));
      }
    }
  }

  std::vector<double> Matrix;     ///< dense M, row-major
  std::vector<double> Packed;     ///< upper triangle of the active block, off-diagonal doubled
  std::array<int, Size> Active{}; ///< indices of the non-zero rows of M
  int ActiveCount = 0;
};

} // namespace cweno
} // namespace sltk
