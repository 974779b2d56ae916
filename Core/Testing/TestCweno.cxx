// SPDX-License-Identifier: BSD-3-Clause
// CWENO / CWENOZ reconstruction from point values (thesis 3.3, 3D by extension).
#include "sltk/interp/Cweno.h"
#include "sltk/interp/Q1.h"

#include "sltk/grid/SampleField.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

namespace
{
using sltk::CwenoInterpolator;
using sltk::CwenoVariant;
using sltk::Index;

constexpr double Lower[3] = { -1.0, -0.8, -0.9 };
constexpr double Upper[3] = { 1.0, 1.1, 0.7 };

const char* variantName(CwenoVariant v)
{
  return v == CwenoVariant::Cweno ? "CWENO" : (v == CwenoVariant::CwenoZ ? "CWENOZ" : "Optimal");
}

/// n nodes per axis on a box with different lengths, so the spacing differs per axis.
template <int D>
sltk::GridSpec<D> box(Index n)
{
  sltk::GridSpec<D> g;
  for (int a = 0; a < D; ++a)
  {
    g.Dims[a] = n;
    g.Origin[a] = Lower[a];
    g.Spacing[a] = (Upper[a] - Lower[a]) / double(n - 1);
    g.Bounds[a] = sltk::Boundary::Extrapolate;
  }
  return g;
}

/// Samples f on every node including the two ghost layers (exact ghosts: these
/// tests measure the reconstruction, not the boundary treatment).
template <int D, class F>
sltk::GridField<D> sampleWithGhosts(const sltk::GridSpec<D>& g, F f)
{
  return sltk::sampleField(g, 2, f, sltk::GhostFill::Exact);
}

/// Deterministic points in the box.
template <int D>
std::vector<std::array<double, D>> randomPoints(int count, unsigned seed)
{
  std::mt19937 gen(seed);
  std::vector<std::array<double, D>> pts(static_cast<size_t>(count));
  for (auto& p : pts)
  {
    for (int a = 0; a < D; ++a)
    {
      p[a] = std::uniform_real_distribution<double>(Lower[a], Upper[a])(gen);
    }
  }
  return pts;
}

/// Calls visit(cell) for every cell of a grid with n nodes per axis, the cell's
/// index along x running fastest; the axes below `firstAxis` keep the index they
/// have in `cell` (a slab of cells).
template <int D, class Visit>
void forEachCell(Index n, Visit visit, std::array<Index, D> cell = {}, int firstAxis = 0)
{
  Index cells = 1;
  for (int a = firstAxis; a < D; ++a)
  {
    cells *= n - 1;
  }
  for (Index c = 0; c < cells; ++c)
  {
    Index rest = c;
    for (int a = firstAxis; a < D; ++a)
    {
      cell[a] = rest % (n - 1);
      rest /= n - 1;
    }
    visit(static_cast<const std::array<Index, D>&>(cell));
  }
}

/// Calls visit(t) for the (perCell + 1)^D local points t of a cell, spaced
/// 1 / perCell in [0, 1]^D (its corners included), t[0] running fastest.
template <int D, class Visit>
void forEachCellPoint(int perCell, Visit visit)
{
  int points = 1;
  for (int a = 0; a < D; ++a)
  {
    points *= perCell + 1;
  }
  for (int p = 0; p < points; ++p)
  {
    std::array<double, D> t{};
    int q = p;
    for (int a = 0; a < D; ++a)
    {
      t[a] = double(q % (perCell + 1)) / double(perCell);
      q /= perCell + 1;
    }
    visit(static_cast<const std::array<double, D>&>(t));
  }
}

double smooth1(const double* x)
{
  return std::sin(3.0 * x[0] + 0.2) + 0.5 * std::exp(x[0]);
}
double smooth2(const double* x)
{
  return std::sin(2.0 * x[0] + 1.0) * std::exp(0.5 * x[1]) + std::cos(1.5 * x[1] - x[0]);
}
double smooth3(const double* x)
{
  return std::sin(2.0 * x[0] + 0.5) * std::cos(1.5 * x[1] - 0.3) * std::exp(0.4 * x[2]);
}

template <int D>
double smooth(const double* x)
{
  return D == 1 ? smooth1(x) : (D == 2 ? smooth2(x) : smooth3(x));
}

struct Convergence
{
  double Error[3] = {};
  double WeightDeviation[3] = {};
  double Tau[3] = {};
  double Spacing[3] = {};
  Index Nodes[3] = {};

  double order(const double* e, int level) const
  {
    return std::log(e[level - 1] / e[level]) / std::log(this->Spacing[level - 1] / this->Spacing[level]);
  }
};

/// Max interpolation error and max |omega - d| over random points, on three grids.
template <int D, CwenoVariant V>
Convergence measure(const Index (&nodes)[3], int points)
{
  Convergence c;
  const auto pts = randomPoints<D>(points, 17u);
  const auto d = CwenoInterpolator<D, V>::linearWeights();
  for (int level = 0; level < 3; ++level)
  {
    const auto g = box<D>(nodes[level]);
    const auto u = sampleWithGhosts(g, smooth<D>);
    CwenoInterpolator<D, V> r(u);
    for (const auto& p : pts)
    {
      const double value = sltk::interpolate(r, g, p.data());
      c.Error[level] = std::max(c.Error[level], std::fabs(value - smooth<D>(p.data())));
      for (int k = 0; k < r.WeightCount; ++k)
      {
        c.WeightDeviation[level] = std::max(c.WeightDeviation[level], std::fabs(r.weights()[k] - d[k]));
      }
      c.Tau[level] = std::max(c.Tau[level], sltk::cweno::globalIndicator(r.indicators()));
    }
    c.Spacing[level] = g.Spacing[0];
    c.Nodes[level] = nodes[level];
  }
  return c;
}

template <int D, CwenoVariant V>
void checkOrder(const Index (&nodes)[3], int points, double expected, double expectedWeightOrder)
{
  const Convergence c = measure<D, V>(nodes, points);
  std::ostringstream os;
  os << std::scientific << std::setprecision(3);
  for (int level = 0; level < 3; ++level)
  {
    os << "    " << D << "D " << variantName(V) << " n=" << c.Nodes[level] << "^" << D << "  max error "
       << c.Error[level] << "  max|w-d| " << c.WeightDeviation[level];
    if (level > 0)
    {
      os << std::fixed << std::setprecision(2) << "  order " << c.order(c.Error, level);
      if (V != CwenoVariant::Optimal)
      {
        os << "  weight order " << c.order(c.WeightDeviation, level) << "  tau order " << c.order(c.Tau, level);
      }
      os << std::scientific << std::setprecision(3);
    }
    os << "\n";
  }
  std::cout << os.str();
  for (int level = 1; level < 3; ++level)
  {
    EXPECT_GE(c.order(c.Error, level), expected - 0.2) << D << "D " << variantName(V) << " level " << level;
    if (V != CwenoVariant::Optimal)
    {
      EXPECT_GE(c.order(c.WeightDeviation, level), expectedWeightOrder - 0.2)
        << D << "D " << variantName(V) << " level " << level;
      // tau of (3.22)/(3.27) and its 3D extension is O(h^4) on smooth data.
      EXPECT_GE(c.order(c.Tau, level), 3.8) << D << "D " << variantName(V) << " level " << level;
    }
  }
}

} // namespace

// --- (1) exactness -----------------------------------------------------------------------------

namespace
{
/// A random tensor polynomial of degree `degree` per axis (x fastest coefficients).
template <int D>
struct TensorPolynomial
{
  int Degree;
  std::vector<double> C;

  TensorPolynomial(int degree, unsigned seed)
    : Degree(degree)
  {
    std::mt19937 gen(seed);
    C.resize(static_cast<size_t>(sltk::cweno::ipow(degree + 1, D)));
    for (auto& c : C)
    {
      c = std::uniform_real_distribution<double>(-1.0, 1.0)(gen);
    }
  }

  double operator()(const double* x) const
  {
    double s = 0.0;
    for (size_t p = 0; p < C.size(); ++p)
    {
      double m = C[p];
      size_t rest = p;
      for (int a = 0; a < D; ++a)
      {
        m *= std::pow(x[a], int(rest % size_t(Degree + 1)));
        rest /= size_t(Degree + 1);
      }
      s += m;
    }
    return s;
  }
};

template <int D, CwenoVariant V>
double maxErrorOnPolynomial(int degree, Index n)
{
  const auto g = box<D>(n);
  const TensorPolynomial<D> f(degree, 5u + D);
  const auto u = sampleWithGhosts(g, [&](const double* x) { return f(x); });
  CwenoInterpolator<D, V> r(u);
  double err = 0.0;
  for (const auto& p : randomPoints<D>(300, 3u))
  {
    err = std::max(err, std::fabs(sltk::interpolate(r, g, p.data()) - f(p.data())));
  }
  return err;
}

template <int D, CwenoVariant V>
double maxNodalError(Index n, unsigned seed)
{
  // Rough random data: the weights are far from optimal, the corners must still be exact.
  const auto g = box<D>(n);
  std::mt19937 gen(seed);
  const auto u = sampleWithGhosts(g, [&](const double*) { return std::uniform_real_distribution<double>(-1, 1)(gen); });
  CwenoInterpolator<D, V> r(u);
  double err = 0.0;
  forEachCell<D>(n,
    [&](const std::array<Index, D>& cell)
    {
      r.prepare(cell);
      for (int corner = 0; corner < (1 << D); ++corner)
      {
        std::array<double, D> t{};
        std::array<Index, D> node = cell;
        for (int a = 0; a < D; ++a)
        {
          t[a] = double((corner >> a) & 1);
          node[a] += (corner >> a) & 1;
        }
        err = std::max(err, std::fabs(r.eval(t) - u(node)));
      }
    });
  return err;
}
} // namespace

TEST(Cweno, OptimalPolynomialReproducesTensorCubics)
{
  EXPECT_LT((maxErrorOnPolynomial<1, CwenoVariant::Optimal>(3, 9)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<2, CwenoVariant::Optimal>(3, 9)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<3, CwenoVariant::Optimal>(3, 7)), 1e-12);
  // A quartic is not reproduced: the check above can fail.
  EXPECT_GT((maxErrorOnPolynomial<1, CwenoVariant::Optimal>(4, 9)), 1e-6);
}

TEST(Cweno, AllVariantsReproduceTensorQuadratics)
{
  // Every polynomial of the combination is exact, whatever the weights.
  EXPECT_LT((maxErrorOnPolynomial<1, CwenoVariant::Cweno>(2, 9)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<1, CwenoVariant::CwenoZ>(2, 9)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<2, CwenoVariant::Cweno>(2, 9)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<2, CwenoVariant::CwenoZ>(2, 9)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<3, CwenoVariant::Cweno>(2, 7)), 1e-12);
  EXPECT_LT((maxErrorOnPolynomial<3, CwenoVariant::CwenoZ>(2, 7)), 1e-12);
  // On cubics the nonlinear weights differ from d_k and the result is not exact.
  EXPECT_GT((maxErrorOnPolynomial<2, CwenoVariant::Cweno>(3, 9)), 1e-9);
}

TEST(Cweno, InterpolatesNodalValuesOnRoughData)
{
  EXPECT_LT((maxNodalError<1, CwenoVariant::Cweno>(30, 1u)), 1e-13);
  EXPECT_LT((maxNodalError<1, CwenoVariant::CwenoZ>(30, 2u)), 1e-13);
  EXPECT_LT((maxNodalError<2, CwenoVariant::Cweno>(12, 3u)), 1e-13);
  EXPECT_LT((maxNodalError<2, CwenoVariant::CwenoZ>(12, 4u)), 1e-13);
  EXPECT_LT((maxNodalError<3, CwenoVariant::Cweno>(6, 5u)), 1e-13);
  EXPECT_LT((maxNodalError<3, CwenoVariant::CwenoZ>(6, 6u)), 1e-13);
}

// --- (2) + (6) orders on smooth data, CWENO and CWENOZ ----------------------------------------

TEST(Cweno, FourthOrderOnSmoothData1D)
{
  const Index n[3] = { 41, 81, 161 };
  checkOrder<1, CwenoVariant::Optimal>(n, 4000, 4.0, 0.0);
  checkOrder<1, CwenoVariant::Cweno>(n, 4000, 4.0, 1.0);
  checkOrder<1, CwenoVariant::CwenoZ>(n, 4000, 4.0, 2.0);
}

TEST(Cweno, FourthOrderOnSmoothData2D)
{
  const Index n[3] = { 21, 41, 81 };
  checkOrder<2, CwenoVariant::Optimal>(n, 4000, 4.0, 0.0);
  checkOrder<2, CwenoVariant::Cweno>(n, 4000, 4.0, 1.0);
  checkOrder<2, CwenoVariant::CwenoZ>(n, 4000, 4.0, 2.0);
}

TEST(Cweno, FourthOrderOnSmoothData3D)
{
  const Index n[3] = { 21, 41, 81 };
  checkOrder<3, CwenoVariant::Optimal>(n, 3000, 4.0, 0.0);
  checkOrder<3, CwenoVariant::Cweno>(n, 3000, 4.0, 1.0);
  checkOrder<3, CwenoVariant::CwenoZ>(n, 3000, 4.0, 2.0);
}

// --- (3) non-oscillation across kinks and jumps -------------------------------------------------

namespace
{
double kinkAtNode(const double* x) // kink on the grid plane x = 0 (a node line of every grid used)
{
  return std::fabs(x[0]) + 0.3 * std::exp(x[1]) + 0.2 * x[2]; // monotone in y, z: extrema at nodes
}

double jumpBetweenNodes(const double* x) // jump on the plane x = 0.013, between nodes
{
  return (x[0] > 0.013 ? 1.0 : 0.0) + 0.1 * std::exp(x[1]) + 0.1 * x[2];
}

template <int D>
double cap(const double* x) // max(1 - |x|^2 / R^2, 0), R = 0.7: kinks on a circle / sphere
{
  return std::max(1.0 - sltktest::squaredNorm<D>(x) / 0.49, 0.0);
}

template <int D>
double ball(const double* x) // jump on the circle / sphere of radius 0.613
{
  return sltktest::squaredNorm<D>(x) < 0.613 * 0.613 ? 1.0 : 0.0;
}

/// Largest excursion of the reconstruction outside [min u, max u] (u: all nodal
/// data, ghosts included), over (perCell + 1)^D points per cell, relative to max u - min u.
template <int D, CwenoVariant V, class F>
double relativeOvershoot(Index n, F f, int perCell)
{
  const auto g = box<D>(n);
  const auto u = sampleWithGhosts(g, [&](const double* x) { return f(x); });
  const auto range = std::minmax_element(u.storage().begin(), u.storage().end());
  const double lo = *range.first;
  const double hi = *range.second;
  CwenoInterpolator<D, V> r(u);
  double over = 0.0;
  forEachCell<D>(n,
    [&](const std::array<Index, D>& cell)
    {
      r.prepare(cell);
      forEachCellPoint<D>(perCell,
        [&](const std::array<double, D>& t)
        {
          const double v = r.eval(t);
          over = std::max(over, std::max(v - hi, lo - v));
        });
    });
  return over / (hi - lo);
}

/// Smallest total weight of the octants on the given side along x (high: bit 0
/// set), over the cells whose x index is `cellX` (all y, z).
template <int D, CwenoVariant V, class F>
double minSideWeight(Index n, F f, Index cellX, bool high)
{
  const auto g = box<D>(n);
  const auto u = sampleWithGhosts(g, [&](const double* x) { return f(x); });
  CwenoInterpolator<D, V> r(u);
  double worst = 1.0;
  std::array<Index, D> slab{};
  slab[0] = cellX;
  forEachCell<D>(
    n,
    [&](const std::array<Index, D>& cell)
    {
      r.prepare(cell);
      double side = 0.0;
      for (int k = 0; k < r.Octants; ++k)
      {
        if (((k & 1) == 1) == high)
        {
          side += r.weights()[1 + k];
        }
      }
      worst = std::min(worst, side);
    },
    slab, 1);
  return worst;
}

template <int D, CwenoVariant V>
void checkAlignedKinkAndJump(Index n, int perCell)
{
  // n odd on [-1, 1]: x = 0 is node m = (n - 1) / 2, the jump at x = 0.013 lies in cell m.
  const Index m = (n - 1) / 2;
  const double kink = relativeOvershoot<D, V>(n, kinkAtNode, perCell);
  const double jump = relativeOvershoot<D, V>(n, jumpBetweenNodes, perCell);
  std::cout << std::scientific << std::setprecision(2) << "    " << D << "D " << variantName(V)
            << " grid-aligned: overshoot kink " << kink << ", jump " << jump;
  EXPECT_LT(kink, 1e-6) << D << "D " << variantName(V);
  EXPECT_LT(jump, 1e-6) << D << "D " << variantName(V);
  // Cells beside the kink / jump: the octants of the smooth side take (almost) all the weight.
  const double w[4] = {
    minSideWeight<D, V>(n, kinkAtNode, m, true),            // cell [0, h]: smooth on the right
    minSideWeight<D, V>(n, kinkAtNode, m - 1, false),       // cell [-h, 0]: smooth on the left
    minSideWeight<D, V>(n, jumpBetweenNodes, m + 1, true),  // right of the jump cell
    minSideWeight<D, V>(n, jumpBetweenNodes, m - 1, false), // left of the jump cell
  };
  std::cout << ", smooth-side weights >= " << std::fixed << std::setprecision(6)
            << std::min(std::min(w[0], w[1]), std::min(w[2], w[3])) << "\n";
  for (double v : w)
  {
    EXPECT_GT(v, 0.99) << D << "D " << variantName(V);
  }
}
} // namespace

TEST(Cweno, NoNewExtremaAcrossGridAlignedKinksAndJumps)
{
  checkAlignedKinkAndJump<1, CwenoVariant::Cweno>(41, 32);
  checkAlignedKinkAndJump<1, CwenoVariant::CwenoZ>(41, 32);
  checkAlignedKinkAndJump<2, CwenoVariant::Cweno>(41, 4);
  checkAlignedKinkAndJump<2, CwenoVariant::CwenoZ>(41, 4);
  checkAlignedKinkAndJump<3, CwenoVariant::Cweno>(21, 2);
  checkAlignedKinkAndJump<3, CwenoVariant::CwenoZ>(21, 2);
  // The same data through the optimal polynomial alone do oscillate (so the checks can fail).
  EXPECT_GT((relativeOvershoot<1, CwenoVariant::Optimal>(41, jumpBetweenNodes, 32)), 0.05);
  EXPECT_GT((relativeOvershoot<2, CwenoVariant::Optimal>(41, jumpBetweenNodes, 4)), 0.03);
  EXPECT_GT((relativeOvershoot<3, CwenoVariant::Optimal>(21, jumpBetweenNodes, 2)), 0.02);
}

TEST(Cweno, NoNewExtremaAcrossKinkAndJumpIn1D)
{
  // 1D: max(1 - x^2/R^2, 0) has its kinks at nodes +-0.7; the jump at 0.613 is between nodes.
  const double capCw = relativeOvershoot<1, CwenoVariant::Cweno>(41, cap<1>, 32);
  const double capZ = relativeOvershoot<1, CwenoVariant::CwenoZ>(41, cap<1>, 32);
  const double ballCw = relativeOvershoot<1, CwenoVariant::Cweno>(41, ball<1>, 32);
  const double ballZ = relativeOvershoot<1, CwenoVariant::CwenoZ>(41, ball<1>, 32);
  std::cout << std::scientific << std::setprecision(2) << "    1D cap: overshoot CWENO " << capCw << ", CWENOZ " << capZ
            << "; 1D jump: CWENO " << ballCw << ", CWENOZ " << ballZ << "\n";
  EXPECT_LT(capCw, 1e-6);
  EXPECT_LT(capZ, 1e-6);
  EXPECT_LT(ballCw, 1e-6);
  EXPECT_LT(ballZ, 1e-6);
}

TEST(Cweno, SmallUndershootsAcrossCurvedKinks)
{
  // A curved kink crosses cells obliquely: then every octant stencil straddles it,
  // and the tensor reconstruction undershoots in the flat region by O(h) (the thesis
  // reports the same for CWENO in Test 4, Table 3.9). Stated tolerance: 1% of the
  // range at h = 0.05 (2D), 2% at h = 0.1 (3D), and a decrease under refinement.
  const double a = relativeOvershoot<2, CwenoVariant::Cweno>(41, cap<2>, 4);
  const double b = relativeOvershoot<2, CwenoVariant::Cweno>(81, cap<2>, 4);
  const double az = relativeOvershoot<2, CwenoVariant::CwenoZ>(41, cap<2>, 4);
  const double c = relativeOvershoot<3, CwenoVariant::Cweno>(21, cap<3>, 2);
  const double cz = relativeOvershoot<3, CwenoVariant::CwenoZ>(21, cap<3>, 2);
  const double jump2 = relativeOvershoot<2, CwenoVariant::Cweno>(41, ball<2>, 4);
  const double jump2Opt = relativeOvershoot<2, CwenoVariant::Optimal>(41, ball<2>, 4);
  const double jump3 = relativeOvershoot<3, CwenoVariant::Cweno>(21, ball<3>, 2);
  const double jump3Opt = relativeOvershoot<3, CwenoVariant::Optimal>(21, ball<3>, 2);
  std::cout << std::scientific << std::setprecision(2) << "    2D cap: CWENO n=41 " << a << ", n=81 " << b
            << ", CWENOZ n=41 " << az << "; 3D cap n=21: CWENO " << c << ", CWENOZ " << cz << "\n"
            << "    curved jumps (not the target of the kink-scaled indicators): 2D disc CWENO " << jump2
            << " (optimal bicubic " << jump2Opt << "), 3D ball CWENO " << jump3 << " (optimal tricubic " << jump3Opt
            << ")\n";
  EXPECT_LT(a, 1e-2);
  EXPECT_LT(az, 1e-2);
  EXPECT_LT(b, 0.6 * a);
  EXPECT_LT(c, 2e-2);
  EXPECT_LT(cz, 2e-2);
  EXPECT_LT(jump2, jump2Opt);
}

// --- (4) the legible entries of (3.20) and of the Appendix ---------------------------------------

namespace
{
/// A = C^T M C: the indicator as a quadratic form of the 4^D stencil data U (x
/// fastest), for the optimal polynomial (octant < 0) or an octant polynomial, on a
/// grid of unit spacing (so the entries are those of (3.20)/(3.26) in units 1/dx^2).
template <int D>
std::vector<double> dataForm(int octant, double delta)
{
  constexpr int size = sltk::cweno::ipow(4, D);
  constexpr int lowSize = sltk::cweno::ipow(3, D);
  std::array<double, D> unit{};
  unit.fill(1.0);
  const sltk::cweno::IndicatorForm<D, 4> formOpt(unit, delta);
  const sltk::cweno::IndicatorForm<D, 3> formLow(unit, delta);
  std::vector<std::vector<double>> z(size);
  for (int p = 0; p < size; ++p)
  {
    double e[size] = {};
    e[p] = 1.0;
    z[p].assign(size, 0.0);
    if (octant < 0)
    {
      sltk::cweno::optimalCoefficients<D>(e, z[p].data());
    }
    else
    {
      sltk::cweno::octantCoefficients<D>(e, octant, z[p].data());
    }
  }
  const int n = octant < 0 ? size : lowSize;
  std::vector<double> a(size * size);
  for (int p = 0; p < size; ++p)
  {
    for (int q = 0; q < size; ++q)
    {
      double s = 0.0;
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          s += z[p][i] * z[q][j] * (octant < 0 ? formOpt.entry(i, j) : formLow.entry(i, j));
        }
      }
      a[size * p + q] = s;
    }
  }
  return a;
}
} // namespace

TEST(Cweno, IndicatorMatricesMatchThesis1D)
{
  // (3.20): A_Q, A_L, A_R (3.3.1), with Delta = dx.
  const double aq[16] = { 4. / 3, -7. / 2, 3, -5. / 6, -7. / 2, 10, -19. / 2, 3, 3, -19. / 2, 10, -7. / 2, -5. / 6, 3,
    -7. / 2, 4. / 3 };
  const double al[16] = { 1, -2, 1, 0, -2, 4, -2, 0, 1, -2, 1, 0, 0, 0, 0, 0 };
  const double ar[16] = { 0, 0, 0, 0, 0, 1, -2, 1, 0, -2, 4, -2, 0, 1, -2, 1 };
  const auto q = dataForm<1>(-1, 1.0);
  const auto l = dataForm<1>(0, 1.0);
  const auto r = dataForm<1>(1, 1.0);
  for (int i = 0; i < 16; ++i)
  {
    EXPECT_NEAR(q[i], aq[i], 1e-12) << i;
    EXPECT_NEAR(l[i], al[i], 1e-12) << i;
    EXPECT_NEAR(r[i], ar[i], 1e-12) << i;
  }
  // Coefficient form just above (3.19): (4 z2^2 + 12 z2 z3 + 48 z3^2) / dx^2.
  const sltk::cweno::IndicatorForm<1, 4> m({ 0.1 }, 0.1);
  EXPECT_NEAR(m.entry(2, 2) * 0.01, 4.0, 1e-12);
  EXPECT_NEAR(m.entry(2, 3) * 0.01, 6.0, 1e-12);
  EXPECT_NEAR(m.entry(3, 3) * 0.01, 48.0, 1e-12);
}

TEST(Cweno, IndicatorFormsOfOneGridAreBuiltOnceAndShared)
{
  using Form = sltk::cweno::IndicatorForm<3, 4>;
  const std::array<double, 3> h{ 0.1, 0.1, 0.2 };
  const double delta = std::sqrt(0.06);
  const Form first(h, delta);
  const Form second(h, delta); // the same spacing and Delta: the first's entries
  Form assigned({ 0.1, 0.1, 0.1 }, delta);
  const Form other(assigned);
  assigned = second;
  EXPECT_TRUE(first.sharesEntriesWith(second));
  EXPECT_TRUE(first.sharesEntriesWith(assigned));
  EXPECT_FALSE(first.sharesEntriesWith(other));
  EXPECT_FALSE(first.sharesEntriesWith(Form(h, 2.0 * delta)));
  EXPECT_NE(first.entry(63, 63), other.entry(63, 63));
  double y[Form::ActiveCount];
  for (int i = 0; i < Form::ActiveCount; ++i)
  {
    y[i] = std::sin(1.0 + i);
  }
  EXPECT_EQ(assigned.ofActive(y), first.ofActive(y)); // the assigned form reads the new entries
  EXPECT_NE(other.ofActive(y), first.ofActive(y));

  // Forms built on several threads at once are one set of entries.
  std::vector<Form> built;
  std::mutex guard;
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
  {
    threads.emplace_back(
      [&]
      {
        const Form f({ 0.3, 0.2, 0.1 }, 0.5);
        const std::lock_guard<std::mutex> lock(guard);
        built.push_back(f);
      });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  for (const Form& f : built)
  {
    EXPECT_TRUE(f.sharesEntriesWith(built.front()));
  }
  // Kept while no form holds them: chunks one after the other build them once.
  const double kept = built.front().entry(21, 42);
  built.clear();
  const std::uint64_t before = Form::builds();
  for (int chunk = 0; chunk < 3; ++chunk)
  {
    EXPECT_EQ(Form({ 0.3, 0.2, 0.1 }, 0.5).entry(21, 42), kept);
  }
  EXPECT_EQ(Form::builds(), before);
  // Past the KeptGrids most recent grids, a grid's forms are built again, to the same values.
  for (size_t g = 0; g < Form::KeptGrids; ++g)
  {
    const Form f({ 0.3, 0.2, 0.1 }, 1.0 + static_cast<double>(g));
  }
  const Form again(h, delta);
  EXPECT_FALSE(again.sharesEntriesWith(first));
  EXPECT_EQ(Form::builds(), before + Form::KeptGrids + 1);
  for (int p = 0; p < Form::Size; p += 7)
  {
    for (int q = 0; q < Form::Size; q += 5)
    {
      EXPECT_EQ(again.entry(p, q), first.entry(p, q));
    }
  }
}

TEST(Cweno, IndicatorMatricesMatchThesisAppendix2D)
{
  // M of (3.25), uniform grid, Delta = sqrt(2) dx (the cell diameter). Tensor index
  // of x^i y^j is i + 4 j; values legible in the Appendix.
  const sltk::cweno::IndicatorForm<2, 4> m({ 1.0, 1.0 }, std::sqrt(2.0));
  auto at = [&](int ix, int iy, int jx, int jy) { return m.entry(ix + 4 * iy, jx + 4 * jy); };
  EXPECT_NEAR(at(3, 3, 3, 3), 721401. / 25, 1e-9);
  EXPECT_NEAR(at(3, 2, 3, 3), 161501. / 70, 1e-10);
  EXPECT_NEAR(at(3, 2, 3, 2), 56076. / 35, 1e-10);
  EXPECT_NEAR(at(3, 2, 2, 3), 737. / 4, 1e-11);
  EXPECT_NEAR(at(3, 1, 3, 3), 933. / 5, 1e-11);
  EXPECT_NEAR(at(3, 1, 3, 2), 954. / 5, 1e-11);
  EXPECT_NEAR(at(3, 1, 3, 1), 989. / 5, 1e-11);
  EXPECT_NEAR(at(2, 2, 2, 2), 3992. / 45, 1e-11);
  EXPECT_NEAR(at(2, 2, 3, 2), 1918. / 15, 1e-11);
  EXPECT_NEAR(at(2, 1, 2, 1), 32. / 3, 1e-12);
  EXPECT_NEAR(at(2, 1, 3, 1), 31. / 2, 1e-12);
  EXPECT_NEAR(at(2, 1, 2, 2), 31. / 3, 1e-12);
  EXPECT_NEAR(at(2, 1, 2, 3), 152. / 15, 1e-12);
  EXPECT_NEAR(at(1, 2, 3, 3), 147. / 10, 1e-12);
  EXPECT_NEAR(at(3, 0, 3, 0), 84.0, 1e-12);
  EXPECT_NEAR(at(1, 1, 1, 1), 1.0, 1e-12);
  EXPECT_EQ(at(1, 0, 1, 0), 0.0); // first derivatives are not in (3.24)

  // A_k and A_opt of (3.26). The Appendix prints them for Delta = dx (not the cell
  // diameter of (3.25): with Delta = sqrt(2) dx the centre entry of A_ne would be
  // 4112/45 instead of 1472/45). Its row layout is garbled; the values, at the data
  // indices i + 4 j of the 4x4 stencil, are these.
  const auto ne = dataForm<2>(3, 1.0);
  const auto sw = dataForm<2>(0, 1.0);
  const auto opt = dataForm<2>(-1, 1.0);
  auto a = [](const std::vector<double>& v, int p, int q) { return v[16 * p + q]; };
  EXPECT_NEAR(a(ne, 5, 5), 3497. / 720, 1e-12);
  EXPECT_NEAR(a(ne, 5, 15), 797. / 720, 1e-12);
  EXPECT_NEAR(a(ne, 15, 15), 857. / 720, 1e-12);
  EXPECT_NEAR(a(ne, 7, 7), 1817. / 720, 1e-12);
  EXPECT_NEAR(a(ne, 7, 15), 827. / 720, 1e-12);
  EXPECT_NEAR(a(ne, 10, 10), 1472. / 45, 1e-11);
  EXPECT_NEAR(a(ne, 10, 11), -1157. / 90, 1e-11);
  EXPECT_NEAR(a(ne, 6, 10), -1547. / 90, 1e-11);
  EXPECT_NEAR(a(ne, 6, 9), 1667. / 180, 1e-11);
  EXPECT_NEAR(a(ne, 5, 6), -623. / 90, 1e-12);
  EXPECT_NEAR(a(ne, 5, 7), 1787. / 720, 1e-12);
  EXPECT_NEAR(a(ne, 11, 15), -109. / 45, 1e-12);
  EXPECT_NEAR(a(ne, 0, 0), 0.0, 1e-14);
  EXPECT_NEAR(a(sw, 0, 0), 857. / 720, 1e-12);
  EXPECT_NEAR(a(sw, 10, 10), 3497. / 720, 1e-12);
  EXPECT_NEAR(a(sw, 5, 5), 1472. / 45, 1e-11);
  EXPECT_NEAR(a(sw, 1, 5), -1157. / 90, 1e-11);
  EXPECT_NEAR(a(opt, 0, 0), 2903. / 1575, 1e-11);
  EXPECT_NEAR(a(opt, 0, 3), -13889. / 12600, 1e-11); // printed once as -13899/12600 (typo)
  EXPECT_NEAR(a(opt, 0, 7), 871553. / 302400, 1e-11);
  EXPECT_NEAR(a(opt, 0, 15), 66427. / 100800, 1e-11);
  EXPECT_NEAR(a(opt, 5, 5), 815527. / 6300, 1e-9);
  EXPECT_NEAR(a(opt, 5, 1), -340087. / 8400, 1e-9);
  EXPECT_NEAR(a(opt, 5, 10), 10709107. / 100800, 1e-9);
  EXPECT_NEAR(a(opt, 5, 6), -2958593. / 25200, 1e-9);
  // With the cell diameter (the scaling used by CwenoInterpolator, Documentation/Numerics.md):
  EXPECT_NEAR(dataForm<2>(3, std::sqrt(2.0))[16 * 10 + 10], 4112. / 45, 1e-11);
}

TEST(Cweno, LineCoefficientsAreTheInverseVandermondeMatrices)
{
  // 3.3.1 on t = -1, 0, 1, 2: rows are the coefficients of t^j, columns the data.
  const double cubic[4][4] = { { 0, 1, 0, 0 }, { -1. / 3, -0.5, 1, -1. / 6 }, { 0.5, -1, 0.5, 0 },
    { -1. / 6, 0.5, -0.5, 1. / 6 } };
  const double left[3][4] = { { 0, 1, 0, 0 }, { -0.5, 0, 0.5, 0 }, { 0.5, -1, 0.5, 0 } };
  const double right[3][4] = { { 0, 1, 0, 0 }, { 0, -1.5, 2, -0.5 }, { 0, 0.5, -1, 0.5 } };
  for (int c = 0; c < 4; ++c)
  {
    double e[4] = {};
    e[c] = 1.0;
    double q[4];
    double l[3];
    double r[3];
    sltk::cweno::optimalCoefficients<1>(e, q);
    sltk::cweno::octantCoefficients<1>(e, 0, l);
    sltk::cweno::octantCoefficients<1>(e, 1, r);
    for (int j = 0; j < 4; ++j)
    {
      EXPECT_NEAR(q[j], cubic[j][c], 1e-15) << "Q, t^" << j << ", data " << c;
      if (j < 3)
      {
        EXPECT_NEAR(l[j], left[j][c], 1e-15) << "P_L, t^" << j << ", data " << c;
        EXPECT_NEAR(r[j], right[j][c], 1e-15) << "P_R, t^" << j << ", data " << c;
      }
    }
  }
}

namespace
{
/// The fast evaluations of IndicatorForm (active monomials, lanes) against z^T M z with the dense M.
template <int D, int N>
void checkIndicatorEvaluation()
{
  using Form = sltk::cweno::IndicatorForm<D, N>;
  std::array<double, D> spacing{};
  for (int a = 0; a < D; ++a)
  {
    spacing[a] = 0.1 + 0.05 * a;
  }
  const Form form(spacing, 0.2);
  std::mt19937 gen(11u + D + N);
  constexpr int lanes = 3;
  std::vector<double> z(static_cast<size_t>(Form::Size) * lanes);
  for (double& v : z)
  {
    v = std::uniform_real_distribution<double>(-1.0, 1.0)(gen);
  }
  constexpr auto active = Form::activeMonomials();
  std::vector<double> y(static_cast<size_t>(Form::ActiveCount) * lanes);
  for (int i = 0; i < Form::ActiveCount; ++i)
  {
    for (int l = 0; l < lanes; ++l)
    {
      y[static_cast<size_t>(i * lanes + l)] = z[static_cast<size_t>(l * Form::Size + active[i])];
    }
  }
  double osc[lanes];
  form.template ofActiveLanes<lanes>(y.data(), osc);
  for (int l = 0; l < lanes; ++l)
  {
    const double* zl = z.data() + static_cast<size_t>(l) * Form::Size;
    double dense = 0.0;
    for (int p = 0; p < Form::Size; ++p)
    {
      for (int q = 0; q < Form::Size; ++q)
      {
        dense += zl[p] * form.entry(p, q) * zl[q];
      }
    }
    EXPECT_NEAR(form(zl), dense, 1e-12 * std::fabs(dense)) << D << "D, N = " << N;
    EXPECT_EQ(osc[l], form(zl)) << D << "D, N = " << N << ": a lane must equal the single evaluation";
  }
}
} // namespace

TEST(Cweno, IndicatorFormEvaluationsMatchTheDenseMatrix)
{
  checkIndicatorEvaluation<1, 3>();
  checkIndicatorEvaluation<1, 4>();
  checkIndicatorEvaluation<2, 3>();
  checkIndicatorEvaluation<2, 4>();
  checkIndicatorEvaluation<3, 3>();
  checkIndicatorEvaluation<3, 4>();
}

// --- (5) convergence condition (3.31): |I_r - I_1| <= C_r max |second increments| ---------------

namespace
{
/// max |v_{k+1} - 2 v_k + v_{k-1}| along every axis, at the nodes of the 4^D stencil of
/// `cell` where the increment is defined inside the stencil.
template <int D>
double largestSecondIncrement(const sltk::GridField<D>& u, const std::array<Index, D>& cell)
{
  const auto& stride = u.strides();
  double second = 0.0;
  for (int s = 0; s < sltk::cweno::ipow(4, D); ++s)
  {
    std::array<Index, D> node = cell;
    int k = s;
    for (int a = 0; a < D; ++a)
    {
      node[a] += k % 4 - 1;
      k /= 4;
    }
    const double* p = u.pointer(node);
    for (int a = 0, sk = s; a < D; ++a, sk /= 4)
    {
      if (sk % 4 == 1 || sk % 4 == 2)
      {
        second = std::max(second, std::fabs(p[stride[a]] - 2.0 * p[0] + p[-stride[a]]));
      }
    }
  }
  return second;
}

/// sup over cells and points of |I_r - I_1| / max |v_{k+1} - 2 v_k + v_{k-1}|, the
/// second increments taken along every axis at the nodes of the 4^D stencil where
/// they are defined inside it (1D: k = i, i + 1, the ones the reconstruction depends on).
template <int D, CwenoVariant V, class F>
double measuredCr(Index n, F data, int perCell)
{
  const auto g = box<D>(n);
  const auto u = sampleWithGhosts(g, data);
  CwenoInterpolator<D, V> r(u);
  sltk::Q1Interpolator<D> q1(u);
  double cr = 0.0;
  forEachCell<D>(n,
    [&](const std::array<Index, D>& cell)
    {
      r.prepare(cell);
      q1.prepare(cell);
      const double second = largestSecondIncrement<D>(u, cell);
      forEachCellPoint<D>(perCell,
        [&](const std::array<double, D>& t)
        {
          const double diff = std::fabs(r.eval(t) - q1.eval(t));
          if (second > 0.0)
          {
            cr = std::max(cr, diff / second);
          }
          else
          {
            EXPECT_LT(diff, 1e-12); // multilinear data: both reconstructions agree
          }
        });
    });
  return cr;
}

/// Random Lipschitz data (constant about 1): noise of amplitude h on a random
/// multi-axis kink pattern, new draws at every call.
template <int D>
struct RandomLipschitz
{
  std::mt19937* Gen;
  double H;
  double Normal[3];
  double operator()(const double* x) const
  {
    double plane = 0.0;
    for (int a = 0; a < D; ++a)
    {
      plane += Normal[a] * x[a];
    }
    return std::fabs(plane) + H * std::uniform_real_distribution<double>(-1.0, 1.0)(*Gen);
  }
};

template <int D, CwenoVariant V>
double worstCr(Index n, int draws, int perCell, unsigned seed)
{
  std::mt19937 gen(seed);
  double worst = 0.0;
  for (int k = 0; k < draws; ++k)
  {
    RandomLipschitz<D> f{ &gen, 2.0 / double(n - 1), {} };
    for (int a = 0; a < D; ++a)
    {
      f.Normal[a] = std::uniform_real_distribution<double>(-1.0, 1.0)(gen);
    }
    worst = std::max(worst, measuredCr<D, V>(n, f, perCell));
  }
  return worst;
}
} // namespace

TEST(Cweno, ConvergenceConditionOnRandomLipschitzData)
{
  // Thesis 3.4: C_r <= (C_3 + 2 d C_2) / (1 - 2 d) = (4/3) 0.2533 + (1/3) (1/8) = 0.380 in 1D.
  const double c1 = worstCr<1, CwenoVariant::Cweno>(201, 20, 16, 11u);
  const double c1z = worstCr<1, CwenoVariant::CwenoZ>(201, 20, 16, 12u);
  const double c2 = worstCr<2, CwenoVariant::Cweno>(21, 10, 4, 13u);
  const double c2z = worstCr<2, CwenoVariant::CwenoZ>(21, 10, 4, 14u);
  const double c3 = worstCr<3, CwenoVariant::Cweno>(9, 4, 2, 15u);
  const double c3z = worstCr<3, CwenoVariant::CwenoZ>(9, 4, 2, 16u);
  std::cout << std::fixed << std::setprecision(4) << "    measured C_r: 1D CWENO " << c1 << ", CWENOZ " << c1z
            << "; 2D CWENO " << c2 << ", CWENOZ " << c2z << "; 3D CWENO " << c3 << ", CWENOZ " << c3z << "\n";
  EXPECT_LT(c1, 0.380);
  EXPECT_LT(c1z, 0.380);
  EXPECT_LT(c2, 1.0);
  EXPECT_LT(c2z, 1.0);
  EXPECT_LT(c3, 1.0);
  EXPECT_LT(c3z, 1.0);
  EXPECT_GT(c1, 0.05); // the measurement is not vacuous
}

TEST(Cweno, FourthOrderThroughPeriodicGhosts2D)
{
  // The production path: interior data, fillGhosts() with periodic wrap, sltk::interpolate().
  double err[3] = {};
  const Index n[3] = { 32, 64, 128 };
  const double twoPi = 8.0 * std::atan(1.0);
  auto f = [](const double* x) { return std::sin(x[0] + 0.3) * std::cos(2.0 * x[1]) + 0.5 * std::sin(x[1]); };
  const auto pts = randomPoints<2>(2000, 29u);
  for (int level = 0; level < 3; ++level)
  {
    sltk::GridSpec<2> g;
    for (int a = 0; a < 2; ++a)
    {
      g.Dims[a] = n[level];
      g.Origin[a] = 0.0;
      g.Spacing[a] = twoPi / double(n[level]);
      g.Bounds[a] = sltk::Boundary::Periodic;
    }
    sltk::GridField<2> u(g, CwenoInterpolator<2>::GhostWidth);
    for (Index k = 0; k < g.nodeCount(); ++k)
    {
      const auto i = u.nodeIndex(k);
      const double x[2] = { g.coordinate(0, i[0]), g.coordinate(1, i[1]) };
      u(i) = f(x);
    }
    u.fillGhosts();
    sltk::CwenoZInterpolator<2> r(u);
    for (const auto& p : pts)
    {
      // points all over the periodic box, including the wrap-around cells
      const double x[2] = { (p[0] + 1.0) * 3.2, (p[1] + 0.8) * 3.4 };
      err[level] = std::max(err[level], std::fabs(sltk::interpolate(r, g, x) - f(x)));
    }
  }
  for (int level = 1; level < 3; ++level)
  {
    const double order = std::log2(err[level - 1] / err[level]);
    std::cout << "    2D CWENOZ periodic n=" << n[level] << "^2: max error " << std::scientific << std::setprecision(3)
              << err[level] << ", order " << std::fixed << std::setprecision(2) << order << "\n";
    EXPECT_GE(order, 3.8) << level;
  }
}

namespace
{
/// buildLanes() (four cells in SIMD lanes, with and without AVX2) against
/// build() cell by cell: the same coefficients bit for bit, on a field with a
/// kink and a jump (weights far from the linear ones) and the boundary cells.
template <int D, CwenoVariant V>
void expectLanesBitwise()
{
  const auto g = box<D>(9);
  const auto field = sampleWithGhosts(g,
    [](const auto& x)
    {
      double r = 0.0;
      for (int a = 0; a < D; ++a)
      {
        r += x[a] * x[a];
      }
      return std::fabs(std::sqrt(r) - 0.5) + (x[0] > 0.3 ? 2.0 : 0.0);
    });
  using Interp = CwenoInterpolator<D, V>;
  Interp one(field);
  std::vector<std::array<Index, D>> cells;
  forEachCell<D>(9, [&](const std::array<Index, D>& c) { cells.push_back(c); });
  constexpr int L = Interp::CellLanes;
  for (size_t first = 0; first + L <= cells.size(); first += 3) // overlapping groups
  {
    std::array<std::array<double, Interp::Size>, L> lanes{};
    std::array<std::array<double, Interp::Size>, L> any{};
    double* to[L];
    double* toAny[L];
    for (int l = 0; l < L; ++l)
    {
      to[l] = lanes[l].data();
      toAny[l] = any[l].data();
    }
    one.buildLanes(&cells[first], to);
    one.buildLanesAny(&cells[first], toAny);
    for (int l = 0; l < L; ++l)
    {
      std::array<double, Interp::Size> expected{};
      one.build(cells[first + l], expected.data());
      for (int q = 0; q < Interp::Size; ++q)
      {
        ASSERT_EQ(lanes[l][q], expected[q]) << variantName(V) << " D=" << D << " cell " << first + l << " q " << q;
        ASSERT_EQ(any[l][q], expected[q]) << variantName(V) << " D=" << D << " cell " << first + l << " q " << q;
      }
    }
  }
}
} // namespace

TEST(Cweno, BuildLanesGiveTheCoefficientsOfBuildBitwise)
{
  expectLanesBitwise<1, CwenoVariant::Cweno>();
  expectLanesBitwise<1, CwenoVariant::CwenoZ>();
  expectLanesBitwise<2, CwenoVariant::Cweno>();
  expectLanesBitwise<2, CwenoVariant::CwenoZ>();
  expectLanesBitwise<2, CwenoVariant::Optimal>();
  expectLanesBitwise<3, CwenoVariant::Cweno>();
  expectLanesBitwise<3, CwenoVariant::CwenoZ>();
}
