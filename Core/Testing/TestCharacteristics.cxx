// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/sl/Characteristics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using Vec2 = std::array<double, 2>;

/// Runs body(tableau, expectedOrder) for Euler, Heun and RK3.
template <class Body>
void forEachMethod(Body&& body)
{
  body(sltk::rkTableau<sltk::RkOrder::Euler>(), 1);
  body(sltk::rkTableau<sltk::RkOrder::Heun>(), 2);
  body(sltk::rkTableau<sltk::RkOrder::Kutta3>(), 3);
}

/// Non-autonomous rotation f_D(t, y) = w(t) J y, J = [0 -1; 1 0], w(t) = 1 + t.
/// With (3.2), y(s) = R(Theta(s)) x where Theta(s) = int_0^s w(tNext - r) dr.
double omega(double t)
{
  return 1.0 + t;
}
double theta(double tNext, double s)
{
  return s * (1.0 + tNext) - 0.5 * s * s;
}
Vec2 rotate(const Vec2& x, double a)
{
  return { std::cos(a) * x[0] - std::sin(a) * x[1], std::sin(a) * x[0] + std::cos(a) * x[1] };
}
Vec2 rotationField(double t, const Vec2& y, int)
{
  return { -omega(t) * y[1], omega(t) * y[0] };
}

/// A running cost depending on time and on both coordinates.
double runningCost(double t, const Vec2& y, int)
{
  return std::cos(t) * y[0] * y[0] + y[1] + 0.5 * y[0] * y[1];
}

/// int_0^dt fC(tNext - s, y(s)) ds on the exact trajectory, composite 3-point Gauss-Legendre.
double exactCost(const Vec2& x, double tNext, double dt)
{
  const int pieces = 256;
  const double h = dt / pieces;
  const double node[3] = { -std::sqrt(0.6), 0.0, std::sqrt(0.6) };
  const double weight[3] = { 5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0 };
  double sum = 0.0;
  for (int p = 0; p < pieces; ++p)
  {
    for (int q = 0; q < 3; ++q)
    {
      const double s = h * (p + 0.5 + 0.5 * node[q]);
      sum += 0.5 * h * weight[q] * runningCost(tNext - s, rotate(x, theta(tNext, s)), 0);
    }
  }
  return sum;
}

double distance(const Vec2& a, const Vec2& b)
{
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}
} // namespace

TEST(Characteristics, TableausAreConsistentAndOfTheStatedOrder)
{
  forEachMethod([](const auto& tab, int order) {
    constexpr int S = std::decay_t<decltype(tab)>::Stages;
    EXPECT_EQ(S, order);
    double sumB = 0.0, sumBC = 0.0, sumBC2 = 0.0, sumBAC = 0.0;
    for (int k = 0; k < S; ++k)
    {
      double rowSum = 0.0;
      for (int j = 0; j < S; ++j)
      {
        if (j >= k)
        {
          EXPECT_EQ(tab.A[k][j], 0.0) << "A must be strictly lower triangular";
        }
        rowSum += tab.A[k][j];
        sumBAC += tab.B[k] * tab.A[k][j] * tab.C[j];
      }
      EXPECT_DOUBLE_EQ(rowSum, tab.C[k]) << "c_k = sum_j A_kj";
      sumB += tab.B[k];
      sumBC += tab.B[k] * tab.C[k];
      sumBC2 += tab.B[k] * tab.C[k] * tab.C[k];
    }
    EXPECT_DOUBLE_EQ(sumB, 1.0);
    if (order >= 2)
    {
      EXPECT_DOUBLE_EQ(sumBC, 0.5);
    }
    if (order >= 3) // (2.56)
    {
      EXPECT_DOUBLE_EQ(sumBC2, 1.0 / 3.0);
      EXPECT_DOUBLE_EQ(sumBAC, 1.0 / 6.0);
    }
  });
  // Run-time dispatch gives the tableau with as many stages as the order.
  for (int o = 1; o <= 3; ++o)
  {
    const int stages = sltk::withTableau(static_cast<sltk::RkOrder>(o), [](const auto& tab) { return tab.Stages; });
    EXPECT_EQ(stages, o);
  }
}

TEST(Characteristics, ConstantFieldGivesExactFootAndStages)
{
  forEachMethod([](const auto& tab, int) {
    constexpr int S = std::decay_t<decltype(tab)>::Stages;
    const Vec2 x = { 0.3, -0.2 };
    const Vec2 c = { 1.5, -0.75 };
    sltk::CharacteristicStages<2, S> st;
    sltk::traceCharacteristic(tab, x, 2.0, 0.4, [&](double, const Vec2&, int) { return c; }, st);
    EXPECT_NEAR(st.Foot[0], x[0] + 0.4 * c[0], 1e-15);
    EXPECT_NEAR(st.Foot[1], x[1] + 0.4 * c[1], 1e-15);
    for (int k = 0; k < S; ++k)
    {
      // The stage values lie on the exact straight characteristic at s = c_k dt, time t_{n+1} - c_k dt.
      EXPECT_NEAR(st.X[k][0], x[0] + tab.C[k] * 0.4 * c[0], 1e-15);
      EXPECT_NEAR(st.X[k][1], x[1] + tab.C[k] * 0.4 * c[1], 1e-15);
      EXPECT_DOUBLE_EQ(st.T[k], 2.0 - tab.C[k] * 0.4);
    }
  });
}

TEST(Characteristics, LinearFieldGivesTruncatedExponential)
{
  // f_D = M y: y(dt) = exp(dt M) x; an explicit RK of order p = stages <= 4 gives exactly
  // sum_{j <= p} (dt M)^j / j! x.
  forEachMethod([](const auto& tab, int order) {
    constexpr int S = std::decay_t<decltype(tab)>::Stages;
    const double m[2][2] = { { 0.3, -1.2 }, { 0.8, -0.5 } };
    auto field = [&](double, const Vec2& y, int) {
      return Vec2{ m[0][0] * y[0] + m[0][1] * y[1], m[1][0] * y[0] + m[1][1] * y[1] };
    };
    const Vec2 x = { 0.7, 0.4 };
    const double dt = 0.3;
    sltk::CharacteristicStages<2, S> st;
    sltk::traceCharacteristic(tab, x, 0.0, dt, field, st);
    Vec2 term = x, expected = x;
    for (int j = 1; j <= order; ++j)
    {
      const Vec2 mt = field(0.0, term, 0);
      term = { dt * mt[0] / j, dt * mt[1] / j };
      expected[0] += term[0];
      expected[1] += term[1];
    }
    EXPECT_NEAR(st.Foot[0], expected[0], 1e-15) << "order " << order;
    EXPECT_NEAR(st.Foot[1], expected[1], 1e-15) << "order " << order;
  });
}

TEST(Characteristics, TimePolynomialFieldIsIntegratedBackwards)
{
  // f_D(t) = polynomial of degree p - 1 in t: the foot x + int_0^dt f_D(tNext - s) ds is exact
  // for order p, and only with the stage times t_{n+1} - c_k dt of (3.8).
  forEachMethod([](const auto& tab, int order) {
    constexpr int S = std::decay_t<decltype(tab)>::Stages;
    const double coef[3] = { 0.4, -1.3, 2.1 };
    auto poly = [&](double t) {
      double v = 0.0;
      for (int j = order - 1; j >= 0; --j)
      {
        v = v * t + coef[j];
      }
      return v;
    };
    auto primitive = [&](double t) { // d/dt = poly
      double v = 0.0;
      for (int j = order - 1; j >= 0; --j)
      {
        v = v * t + coef[j] / (j + 1);
      }
      return v * t;
    };
    const double tNext = 1.7, dt = 0.45;
    sltk::CharacteristicStages<1, S> st;
    sltk::traceCharacteristic(tab, std::array<double, 1>{ 0.25 }, tNext, dt,
      [&](double t, const std::array<double, 1>&, int) { return std::array<double, 1>{ poly(t) }; }, st);
    EXPECT_NEAR(st.Foot[0], 0.25 + primitive(tNext) - primitive(tNext - dt), 1e-14) << "order " << order;
  });
}

TEST(Characteristics, StageIndexSelectsThePerStageControl)
{
  // (3.8): stage k uses a_k. With f_D = a_k (constant per stage) the foot is x + dt sum b_k a_k.
  const auto tab = sltk::rkTableau<sltk::RkOrder::Kutta3>();
  const double a[3] = { 1.0, -2.0, 5.0 };
  sltk::CharacteristicStages<1, 3> st;
  sltk::traceCharacteristic(tab, std::array<double, 1>{ 0.0 }, 1.0, 0.1,
    [&](double, const std::array<double, 1>&, int k) { return std::array<double, 1>{ a[k] }; }, st);
  EXPECT_NEAR(st.Foot[0], 0.1 * (a[0] / 6.0 + 2.0 * a[1] / 3.0 + a[2] / 6.0), 1e-15);
  EXPECT_NEAR(st.X[1][0], 0.1 * 0.5 * a[0], 1e-15);
  EXPECT_NEAR(st.X[2][0], 0.1 * (-a[0] + 2.0 * a[1]), 1e-15);
  const double c = sltk::stageQuadrature(tab, st, 0.1, [&](double, const std::array<double, 1>&, int k) { return a[k]; });
  EXPECT_NEAR(c, 0.1 * (a[0] / 6.0 + 2.0 * a[1] / 3.0 + a[2] / 6.0), 1e-15);
}

TEST(Characteristics, FeetConvergeWithTheOrderOfTheMethod)
{
  // Trace back from T = 2 to 0 through n steps on a non-autonomous rotation; global order p.
  forEachMethod([](const auto& tab, int order) {
    constexpr int S = std::decay_t<decltype(tab)>::Stages;
    const Vec2 x = { 0.6, 0.2 };
    const double tEnd = 2.0;
    double err[3];
    for (int level = 0; level < 3; ++level)
    {
      const int n = 40 << level;
      const double dt = tEnd / n;
      Vec2 y = x;
      sltk::CharacteristicStages<2, S> st;
      for (int m = 0; m < n; ++m)
      {
        sltk::traceCharacteristic(tab, y, tEnd - m * dt, dt, rotationField, st);
        y = st.Foot;
      }
      err[level] = distance(y, rotate(x, theta(tEnd, tEnd)));
    }
    for (int level = 1; level < 3; ++level)
    {
      const double observed = std::log2(err[level - 1] / err[level]);
      EXPECT_GE(observed, order - 0.2) << "order " << order << " level " << level << " err " << err[level];
    }
  });
}

TEST(Characteristics, StageQuadratureConvergesWithTheOrderOfTheMethod)
{
  // (2.46)-(2.56): the cost with weights b_k on the stage values X_k, stage times t_{n+1} - c_k dt.
  // Local error O(dt^{p+1}) on one step (for RK3 although X_2, X_3 are only O(dt^2) accurate,
  // (2.54)), and order p for the total cost along the traced characteristic.
  forEachMethod([](const auto& tab, int order) {
    constexpr int S = std::decay_t<decltype(tab)>::Stages;
    const Vec2 x = { 0.6, 0.2 };
    const double tEnd = 2.0;
    double local[3], global[3];
    for (int level = 0; level < 3; ++level)
    {
      sltk::CharacteristicStages<2, S> st;
      const double h = 0.05 / (1 << level);
      sltk::traceCharacteristic(tab, x, tEnd, h, rotationField, st);
      local[level] = std::fabs(sltk::stageQuadrature(tab, st, h, runningCost) - exactCost(x, tEnd, h));

      const int n = 40 << level;
      const double dt = tEnd / n;
      Vec2 y = x;
      double cost = 0.0;
      for (int m = 0; m < n; ++m)
      {
        sltk::traceCharacteristic(tab, y, tEnd - m * dt, dt, rotationField, st);
        cost += sltk::stageQuadrature(tab, st, dt, runningCost);
        y = st.Foot;
      }
      global[level] = std::fabs(cost - exactCost(x, tEnd, tEnd));
    }
    for (int level = 1; level < 3; ++level)
    {
      EXPECT_GE(std::log2(local[level - 1] / local[level]), order + 1 - 0.2)
        << "order " << order << " level " << level << " local err " << local[level];
      EXPECT_GE(std::log2(global[level - 1] / global[level]), order - 0.2)
        << "order " << order << " level " << level << " global err " << global[level];
    }
  });
}
