// SPDX-License-Identifier: BSD-3-Clause
// The thesis's chapter 5 interpolation (5.5) on a uniform grid: the nearest
// node's constrained least-squares Q1 polynomial.
#include "sltk/interp/LsqQ1.h"

#include "sltk/grid/SampleField.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace
{
/// Solves the small dense system A c = b (Gaussian elimination, partial pivoting).
std::vector<double> solve(std::vector<std::vector<double>> a, std::vector<double> b)
{
  const size_t n = b.size();
  for (size_t k = 0; k < n; ++k)
  {
    size_t pivot = k;
    for (size_t r = k + 1; r < n; ++r)
    {
      pivot = std::fabs(a[r][k]) > std::fabs(a[pivot][k]) ? r : pivot;
    }
    std::swap(a[k], a[pivot]);
    std::swap(b[k], b[pivot]);
    for (size_t r = k + 1; r < n; ++r)
    {
      const double f = a[r][k] / a[k][k];
      for (size_t c = k; c < n; ++c)
      {
        a[r][c] -= f * a[k][c];
      }
      b[r] -= f * b[k];
    }
  }
  std::vector<double> c(n);
  for (size_t k = n; k-- > 0;)
  {
    double s = b[k];
    for (size_t j = k + 1; j < n; ++j)
    {
      s -= a[k][j] * c[j];
    }
    c[k] = s / a[k][k];
  }
  return c;
}

/// (5.5) solved as written: the Q1 monomials m_S(x') = prod_{a in S} x'_a, S
/// a non-empty subset of the axes, fitted by least squares (normal
/// equations) to phi(neighbour) - phi_i over the 3^D - 1 neighbours of node
/// `i`, then evaluated at x' (in cells); c_0 = phi_i is the constraint.
template <int D>
double constrainedLeastSquares(const sltk::GridField<D>& u, const std::array<sltk::Index, D>& i, const double* x)
{
  constexpr int Terms = (1 << D) - 1;
  const auto monomial = [](int subset, const double* y)
  {
    double m = 1.0;
    for (int a = 0; a < D; ++a)
    {
      m *= (subset >> a) & 1 ? y[a] : 1.0;
    }
    return m;
  };
  std::vector<std::vector<double>> normal(Terms, std::vector<double>(Terms, 0.0));
  std::vector<double> right(Terms, 0.0);
  for (int c = 0; c < sltk::ipow(3, D); ++c)
  {
    double offset[D];
    std::array<sltk::Index, D> j = i;
    for (int a = 0, rest = c; a < D; ++a, rest /= 3)
    {
      offset[a] = rest % 3 - 1.0;
      j[a] += rest % 3 - 1;
    }
    const double residual = u(j) - u(i);
    for (int r = 0; r < Terms; ++r)
    {
      for (int s = 0; s < Terms; ++s)
      {
        normal[r][s] += monomial(r + 1, offset) * monomial(s + 1, offset);
      }
      right[r] += monomial(r + 1, offset) * residual;
    }
  }
  const std::vector<double> coefficients = solve(normal, right);
  double p = u(i);
  for (int r = 0; r < Terms; ++r)
  {
    p += coefficients[r] * monomial(r + 1, x);
  }
  return p;
}

template <int D>
void expectTheConstrainedFit(int samples)
{
  const auto g = sltk::uniformBox<D>(9, -1.0, 1.0);
  const auto f = [](const double* x)
  {
    double v = std::sin(2.0 * x[0]) + x[0] * x[0];
    for (int a = 1; a < D; ++a)
    {
      v += std::cos(1.5 * x[a] + a) * (1.0 + x[0]);
    }
    return v;
  };
  const auto u = sltk::sampleField(g, 2, f);
  sltk::LsqQ1Interpolator<D> lsq(u);
  for (int s = 0; s < samples; ++s)
  {
    double x[D];
    std::array<sltk::Index, D> nearest{};
    double local[D];
    for (int a = 0; a < D; ++a)
    {
      x[a] = 0.9 * std::sin(1.3 * s + 0.7 * a + 0.2 * a * s);
      const double at = (x[a] - g.Origin[a]) / g.Spacing[a];
      nearest[a] = static_cast<sltk::Index>(std::lround(at));
      local[a] = at - static_cast<double>(nearest[a]);
    }
    EXPECT_NEAR(sltk::interpolate(lsq, g, x), constrainedLeastSquares<D>(u, nearest, local), 1e-12) << "sample " << s;
  }
}
} // namespace

TEST(LsqQ1, IsTheConstrainedLeastSquaresFitOfTheNearestNodeIn2DAnd3D)
{
  expectTheConstrainedFit<2>(300);
  expectTheConstrainedFit<3>(300);
}

TEST(LsqQ1, ReproducesMultilinearFunctionsAndNodalValues)
{
  const auto g = sltk::uniformBox<3>(7, -1.0, 1.0);
  const auto f = [](const double* x) { return 1.0 + x[0] - 2.0 * x[1] + 0.5 * x[0] * x[1] * x[2] - x[1] * x[2]; };
  const auto u = sltk::sampleField(g, 2, f);
  sltk::LsqQ1Interpolator<3> lsq(u);
  for (int s = 0; s < 200; ++s)
  {
    const double x[3] = { 0.95 * std::sin(s * 1.3), 0.95 * std::cos(s * 0.7), 0.95 * std::sin(s * 2.9 + 1.0) };
    EXPECT_NEAR(sltk::interpolate(lsq, g, x), f(x), 1e-13);
  }
  const auto h = sltk::uniformBox<2>(9, -1.0, 1.0);
  const auto wavy = [](const double* x) { return std::exp(x[0]) * std::sin(3 * x[1]); };
  const auto v = sltk::sampleField(h, 2, wavy);
  sltk::LsqQ1Interpolator<2> at(v);
  for (sltk::Index k = 0; k < h.nodeCount(); ++k)
  {
    const auto i = v.nodeIndex(k);
    const double x[2] = { h.coordinate(0, i[0]), h.coordinate(1, i[1]) };
    EXPECT_EQ(sltk::interpolate(at, h, x), v(i)); // the centre constraint c_0 = phi_i
  }
}

TEST(LsqQ1, JumpsWhereTheNearestNodeChanges)
{
  // The thesis's remark (5.3.1): no continuity between cells. On x^3 in 1D,
  // node i's line has the central slope 3 x_i^2 + h^2; the lines of nodes i
  // and i + 1 differ by -1.5 h^3 half-way between them (on x^2 they would
  // meet there: tangents of a parabola).
  const auto g = sltk::uniformBox<1>(11, -1.0, 1.0);
  const auto u = sltk::sampleField(g, 2, [](const double* x) { return x[0] * x[0] * x[0]; });
  sltk::LsqQ1Interpolator<1> lsq(u);
  const double h = g.Spacing[0], mid = g.coordinate(0, 6) + 0.5 * h;
  const double below[1] = { mid - 1e-9 }, above[1] = { mid + 1e-9 };
  const double jump = sltk::interpolate(lsq, g, above) - sltk::interpolate(lsq, g, below);
  EXPECT_NEAR(jump, -1.5 * h * h * h, 1e-7);
  EXPECT_GT(std::fabs(jump), 1e-3);
}

TEST(LsqQ1, ReadStraightFromTheFieldItGivesTheCachedValuesBitForBit)
{
  // The level-set step reads the 3^D nodes around each foot's nearest node
  // (evalAt, LevelSetStep.h) instead of caching the cell's 4^D (eval).
  const auto g = sltk::uniformBox<3>(9, -1.0, 1.0);
  const auto u = sltk::sampleField(g, 2, [](const double* x) { return std::sin(3.0 * x[0]) * std::exp(x[1] - x[2]); });
  sltk::LsqQ1Interpolator<3> cached(u);
  const auto around = sltk::stencilOffsets<3, 3>(u.strides(), -1);
  for (int s = 0; s < 500; ++s)
  {
    const double x[3] = { 0.99 * std::sin(s * 1.7), 0.99 * std::cos(s * 0.3 + 0.4), 0.99 * std::sin(s * 2.3 + 1.0) };
    const auto loc = sltk::locate(g, x);
    cached.prepare(loc.Cell);
    EXPECT_EQ(sltk::LsqQ1Interpolator<3>::evalAt(u, around, loc), cached.eval(loc.Local)) << "sample " << s;
  }
}
