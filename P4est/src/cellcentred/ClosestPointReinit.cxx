// SPDX-License-Identifier: GPL-2.0-or-later
#include "ClosestPointReinit.h"

#include "Propagation.h"

#include "sltk/levelset/CutOff.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace sltk
{
namespace p4est
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
  const std::vector<CellPolynomial<D>>& polynomials, double gamma, const Context& ctx, std::vector<double>& phi,
  const CellTree<D>* tree)
{
  ClosestPointReport report;
  const int n = graph.size();
  constexpr int Subcells = 1 << D;
  // 1. T_0 among this rank's leaves; the ghosts' membership from their owners.
  std::vector<char> inFront(static_cast<size_t>(n), 0);
  std::vector<int> front;
  for (int i = 0; i < graph.Owned; ++i)
  {
    for (int k = graph.Offsets[static_cast<size_t>(i)]; k < graph.Offsets[static_cast<size_t>(i) + 1]; ++k)
    {
      if (phi[static_cast<size_t>(i)] * phi[static_cast<size_t>(graph.Neighbours[static_cast<size_t>(k)])] <= 0.0)
      {
        inFront[static_cast<size_t>(i)] = 1;
        front.push_back(i);
        break;
      }
    }
  }
  if (tree)
  {
    tree->syncGhosts(inFront);
  }
  report.FrontLeaves = static_cast<int>(front.size());
  // 2. Seeds: the subcell centres x_i + (+-h/4, ...) of T_0's leaves (and ghosts), projected.
  std::vector<int> seeded = front;
  for (int i = graph.Owned; i < n; ++i)
  {
    if (inFront[static_cast<size_t>(i)])
    {
      seeded.push_back(i);
    }
  }
  std::vector<int> firstSeed(static_cast<size_t>(n), -1); // slot of a seeded leaf's first subcell
  for (size_t f = 0; f < seeded.size(); ++f)
  {
    firstSeed[static_cast<size_t>(seeded[f])] = static_cast<int>(f * Subcells);
  }
  std::vector<std::array<double, D>> seeds(seeded.size() * Subcells);
  std::vector<char> converged(seeds.size());
  ctx.parallelFor(0, static_cast<Index>(seeded.size()),
    [&](Index b, Index e)
    {
      for (Index f = b; f < e; ++f)
      {
        const size_t i = static_cast<size_t>(seeded[static_cast<size_t>(f)]);
        const double h = graph.Sizes[i];
        for (int s = 0; s < Subcells; ++s)
        {
          const size_t slot = static_cast<size_t>(f) * Subcells + static_cast<size_t>(s);
          for (int a = 0; a < D; ++a)
          {
            seeds[slot][a] = graph.Centres[i][a] + ((s >> a) & 1 ? 0.25 : -0.25) * h;
          }
          converged[slot] = projectOntoZero<D>(polynomials[i], h, seeds[slot]) ? 1 : 0;
        }
      }
    });
  for (const char c : converged)
  {
    report.Seeds += c;
  }
  // 3. Closest points of T_0, each from the nearest seed of its leaf, its
  // neighbours and theirs (ties: the first in Morton order, then subcell order).
  std::vector<std::array<double, D>> closest(front.size());
  std::vector<char> outcome(front.size()); // 0 Newton converged, 1 fell back to the seed, 2 no seed
  ctx.parallelFor(0, static_cast<Index>(front.size()),
    [&](Index b, Index e)
    {
      for (Index f = b; f < e; ++f)
      {
        const size_t i = static_cast<size_t>(front[static_cast<size_t>(f)]);
        const auto& x = graph.Centres[i];
        double nearest = std::numeric_limits<double>::infinity();
        int seed = -1, seedLeaf = -1;
        const auto consider = [&](int leaf)
        {
          const int first = firstSeed[static_cast<size_t>(leaf)];
          for (int s = 0; first >= 0 && s < Subcells; ++s)
          {
            const size_t slot = static_cast<size_t>(first + s);
            if (!converged[slot])
            {
              continue;
            }
            const double r = pointDistance<D>(x, seeds[slot]);
            const bool before = seedLeaf >= 0 &&
              graph.GlobalIds[static_cast<size_t>(leaf)] < graph.GlobalIds[static_cast<size_t>(seedLeaf)];
            if (r < nearest || (r == nearest && seed >= 0 && before))
            {
              nearest = r;
              seed = static_cast<int>(slot);
              seedLeaf = leaf;
            }
          }
        };
        consider(static_cast<int>(i));
        for (int k = graph.Offsets[i]; k < graph.Offsets[i + 1]; ++k)
        {
          const size_t j = static_cast<size_t>(graph.Neighbours[static_cast<size_t>(k)]);
          consider(static_cast<int>(j));
          for (int l = graph.Offsets[j]; l < graph.Offsets[j + 1]; ++l)
          {
            consider(graph.Neighbours[static_cast<size_t>(l)]);
          }
        }
        std::array<double, D>& y = closest[static_cast<size_t>(f)];
        if (seed < 0)
        {
          outcome[static_cast<size_t>(f)] = 2;
          continue;
        }
        y = seeds[static_cast<size_t>(seed)];
        const size_t owner = static_cast<size_t>(seedLeaf);
        if (!closestPoint<D>(polynomials[owner], graph.Sizes[owner], x, y))
        {
          y = seeds[static_cast<size_t>(seed)];
          outcome[static_cast<size_t>(f)] = 1;
        }
      }
    });
  Propagation<D> state;
  resetPropagation(n, state);
  std::vector<int> fixed;
  for (size_t f = 0; f < front.size(); ++f)
  {
    if (outcome[f] == 2)
    {
      ++report.Unseeded;
      continue;
    }
    const size_t i = static_cast<size_t>(front[f]);
    state.Distance[i] = pointDistance<D>(graph.Centres[i], closest[f]);
    state.Reference[i] = closest[f];
    state.Fixed[i] = 1;
    report.SeedFallbacks += outcome[f];
    fixed.push_back(front[f]);
  }
  // 4. The rest, by propagation up to gamma.
  propagate(graph, fixed, state, gamma, tree);
  for (int i = 0; i < graph.Owned; ++i)
  {
    const double sign = phi[static_cast<size_t>(i)] < 0.0 ? -1.0 : 1.0;
    phi[static_cast<size_t>(i)] = cutLevel(sign * state.Distance[static_cast<size_t>(i)], gamma);
  }
  return report;
}

template ClosestPointReport reinitialiseByClosestPoints(const LeafGraph<2>&, const std::vector<CellPolynomial<2>>&,
  double, const Context&, std::vector<double>&, const CellTree<2>*);
template ClosestPointReport reinitialiseByClosestPoints(const LeafGraph<3>&, const std::vector<CellPolynomial<3>>&,
  double, const Context&, std::vector<double>&, const CellTree<3>*);

} // namespace p4est
} // namespace sltk
