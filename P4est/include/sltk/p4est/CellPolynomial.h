// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file CellPolynomial.h
/// The polynomial of one leaf in the thesis's cell-centred scheme (5.2.1):
/// Q1, the tensor product of degree one in each variable,
///   p(x) = sum over the subsets S of the axes of C_S prod_{a in S} (x_a - c_a),
/// (in 2D the basis {1, x_1, x_2, x_1 x_2} of (5.5)), with c the centre of the
/// leaf it was fitted on and C_{} = p(c) (the centre constraint of (5.5)).
/// Kept in physical units, so that a child inherits its parent's polynomial
/// as it is (5.2.2, "inherited by the children"; c stays the parent's, and
/// slope() is the gradient there) and a coarsened family averages its
/// children's coefficients.

#include <array>

namespace sltk
{
namespace p4est
{

template <int D>
struct CellPolynomial
{
  static constexpr int Terms = 1 << D;
  std::array<double, D> Centre{};
  /// C[S] multiplies prod_{a in S} (x_a - c_a), S a bit mask of the axes; C[0] is the value at the centre.
  std::array<double, Terms> C{};

  double value() const { return this->C[0]; }
  /// The gradient at the centre c.
  std::array<double, D> slope() const
  {
    std::array<double, D> g;
    for (int a = 0; a < D; ++a)
    {
      g[a] = this->C[1 << a];
    }
    return g;
  }

  double eval(const std::array<double, D>& x) const
  {
    double sum = 0.0;
    for (int s = 0; s < Terms; ++s)
    {
      double term = this->C[s];
      for (int a = 0; a < D; ++a)
      {
        term *= (s >> a) & 1 ? x[a] - this->Centre[a] : 1.0;
      }
      sum += term;
    }
    return sum;
  }

  std::array<double, D> gradient(const std::array<double, D>& x) const
  {
    std::array<double, D> g{};
    for (int a = 0; a < D; ++a)
    {
      for (int s = 0; s < Terms; ++s)
      {
        if (!((s >> a) & 1))
        {
          continue;
        }
        double term = this->C[s];
        for (int b = 0; b < D; ++b)
        {
          term *= b != a && ((s >> b) & 1) ? x[b] - this->Centre[b] : 1.0;
        }
        g[a] += term;
      }
    }
    return g;
  }

  /// Second derivatives (zero on the diagonal: degree one in each variable).
  std::array<std::array<double, D>, D> hessian(const std::array<double, D>& x) const
  {
    std::array<std::array<double, D>, D> h{};
    for (int a = 0; a < D; ++a)
    {
      for (int b = a + 1; b < D; ++b)
      {
        for (int s = 0; s < Terms; ++s)
        {
          if (!((s >> a) & 1) || !((s >> b) & 1))
          {
            continue;
          }
          double term = this->C[s];
          for (int e = 0; e < D; ++e)
          {
            term *= e != a && e != b && ((s >> e) & 1) ? x[e] - this->Centre[e] : 1.0;
          }
          h[a][b] += term;
        }
        h[b][a] = h[a][b];
      }
    }
    return h;
  }
};

} // namespace p4est
} // namespace sltk
