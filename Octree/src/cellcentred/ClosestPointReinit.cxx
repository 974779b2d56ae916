// SPDX-License-Identifier: GPL-2.0-or-later
#include "ClosestPointReinit.h"

#include "Propagation.h"

#include "sltk/cloud/PointLocator.h"
#include "sltk/levelset/CutOff.h"

#include <Eigen/Dense>

#include <cmath>

namespace sltk
{
namespace octree
{

namespace
{
constexpr int NewtonSteps = 20;
constexpr double NewtonTolerance = 1e-10; ///< of the leaf's size

/// Step 2: y moved along the gradient onto p = 0; false when it does not
/// converge or leaves the leaf's neighbourhood (|y - x_i| > h on an axis).
template <int D>
bool projectOntoZero(const CellPolynomial<D>& p, double h, std::array<double, D>& y)
{
  for (int it = 0; it < NewtonSteps; ++it)
  {
    const auto g = p.gradient(y);
    double gg = 0.0;
    for (int a = 0; a < D; ++a)
    {
      gg += g[a] * g[a];
    }
    if (!(gg > 0.0))
    {
      return false;
    }
    const double t = p.eval(y) / gg;
    for (int a = 0; a < D; ++a)
    {
      y[a] -= t * g[a];
      if (std::fabs(y[a] - p.Centre[a]) > h)
      {
        return false;
      }
    }
    if (std::fabs(t) * std::sqrt(gg) < NewtonTolerance * h)
    {
      return true;
    }
  }
  return false;
}

/// Step 3: Newton's method on the Lagrangian of min |y - x| subject to
/// p(y) = 0 (Saye's method): y - x + lambda grad p(y) = 0, p(y) = 0, from
/// the seed; steps limited to half a leaf. False when it does not converge
/// or moves beyond 1.5 leaves from the seed.
template <int D>
bool closestPoint(const CellPolynomial<D>& p, double h, const std::array<double, D>& x, std::array<double, D>& y)
{
  using Vector = Eigen::Matrix<double, D + 1, 1>;
  using Matrix = Eigen::Matrix<double, D + 1, D + 1>;
  const std::array<double, D> seed = y;
  auto g = p.gradient(y);
  double gg = 0.0, lambda = 0.0;
  for (int a = 0; a < D; ++a)
  {
    gg += g[a] * g[a];
    lambda += (x[a] - y[a]) * g[a];
  }
  if (!(gg > 0.0))
  {
    return false;
  }
  lambda /= gg;
  for (int it = 0; it < NewtonSteps; ++it)
  {
    g = p.gradient(y);
    const auto hessian = p.hessian(y);
    Matrix jacobian = Matrix::Zero();
    Vector residual;
    for (int a = 0; a < D; ++a)
    {
      for (int b = 0; b < D; ++b)
      {
        jacobian(a, b) = (a == b ? 1.0 : 0.0) + lambda * hessian[a][b];
      }
      jacobian(a, D) = jacobian(D, a) = g[a];
      residual[a] = y[a] - x[a] + lambda * g[a];
    }
    residual[D] = p.eval(y);
    Vector step = jacobian.fullPivLu().solve(-residual);
    if (!step.allFinite())
    {
      return false;
    }
    const double length = step.template head<D>().norm();
    if (length > 0.5 * h)
    {
      step *= 0.5 * h / length;
    }
    for (int a = 0; a < D; ++a)
    {
      y[a] += step[a];
    }
    lambda += step[D];
    if (pointDistance<D>(y, seed) > 1.5 * h)
    {
      return false;
    }
    if (std::min(length, 0.5 * h) < NewtonTolerance * h)
    {
      return true;
    }
  }
  return false;
}

} // namespace

template <int D>
ClosestPointReport reinitialiseByClosestPoints(const LeafGraph<D>& graph,
  const std::vector<CellPolynomial<D>>& polynomials, double gamma, const Context& ctx, std::vector<double>& phi)
{
  ClosestPointReport report;
  const int n = graph.size();
  // 1. T_0.
  std::vector<int> front;
  for (int i = 0; i < n; ++i)
  {
    for (int k = graph.Offsets[static_cast<size_t>(i)]; k < graph.Offsets[static_cast<size_t>(i) + 1]; ++k)
    {
      if (phi[static_cast<size_t>(i)] * phi[static_cast<size_t>(graph.Neighbours[static_cast<size_t>(k)])] <= 0.0)
      {
        front.push_back(i);
        break;
      }
    }
  }
  report.FrontLeaves = static_cast<int>(front.size());
  // 2. Seeds: the subcell centres x_i + (+-h/4, ...), projected.
  constexpr int Subcells = 1 << D;
  std::vector<std::array<double, D>> projected(front.size() * Subcells);
  std::vector<char> converged(projected.size());
  ctx.parallelFor(0, static_cast<Index>(front.size()),
    [&](Index b, Index e)
    {
      for (Index f = b; f < e; ++f)
      {
        const size_t i = static_cast<size_t>(front[static_cast<size_t>(f)]);
        const double h = graph.Sizes[i];
        for (int s = 0; s < Subcells; ++s)
        {
          const size_t slot = static_cast<size_t>(f) * Subcells + static_cast<size_t>(s);
          for (int a = 0; a < D; ++a)
          {
            projected[slot][a] = graph.Centres[i][a] + ((s >> a) & 1 ? 0.25 : -0.25) * h;
          }
          converged[slot] = projectOntoZero<D>(polynomials[i], h, projected[slot]) ? 1 : 0;
        }
      }
    });
  PointCloud<D> seeds;
  std::vector<int> seedLeaf;
  for (size_t slot = 0; slot < projected.size(); ++slot)
  {
    if (converged[slot])
    {
      seeds.Points.push_back(projected[slot]);
      seedLeaf.push_back(front[slot / Subcells]);
    }
  }
  report.Seeds = static_cast<int>(seeds.Points.size());
  Propagation<D> state;
  resetPropagation(n, state);
  if (!seeds.Points.empty())
  {
    const PointLocator<D> locator(seeds);
    // 3. Closest points of T_0.
    std::vector<std::array<double, D>> closest(front.size());
    std::vector<char> fellBack(front.size());
    ctx.parallelFor(0, static_cast<Index>(front.size()),
      [&](Index b, Index e)
      {
        for (Index f = b; f < e; ++f)
        {
          const auto& x = graph.Centres[static_cast<size_t>(front[static_cast<size_t>(f)])];
          const auto hit = locator.nearest(x);
          const size_t owner = static_cast<size_t>(seedLeaf[static_cast<size_t>(hit.Index)]);
          std::array<double, D>& y = closest[static_cast<size_t>(f)];
          y = seeds.Points[static_cast<size_t>(hit.Index)];
          if (!closestPoint<D>(polynomials[owner], graph.Sizes[owner], x, y))
          {
            y = seeds.Points[static_cast<size_t>(hit.Index)];
            fellBack[static_cast<size_t>(f)] = 1;
          }
        }
      });
    for (size_t f = 0; f < front.size(); ++f)
    {
      const size_t i = static_cast<size_t>(front[f]);
      state.Distance[i] = pointDistance<D>(graph.Centres[i], closest[f]);
      state.Reference[i] = closest[f];
      state.Fixed[i] = 1;
      report.SeedFallbacks += fellBack[f];
    }
    // 4. The rest, by propagation up to gamma.
    propagate(graph, front, state, gamma);
  }
  for (int i = 0; i < n; ++i)
  {
    const double sign = phi[static_cast<size_t>(i)] < 0.0 ? -1.0 : 1.0;
    phi[static_cast<size_t>(i)] = cutLevel(sign * state.Distance[static_cast<size_t>(i)], gamma);
  }
  return report;
}

template ClosestPointReport reinitialiseByClosestPoints(
  const LeafGraph<2>&, const std::vector<CellPolynomial<2>>&, double, const Context&, std::vector<double>&);
template ClosestPointReport reinitialiseByClosestPoints(
  const LeafGraph<3>&, const std::vector<CellPolynomial<3>>&, double, const Context&, std::vector<double>&);

} // namespace octree
} // namespace sltk
