// SPDX-License-Identifier: GPL-2.0-or-later
#include "CellEnergy.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace sltk
{
namespace p4est
{

namespace
{
using Point2 = std::array<double, 2>;
using Point3 = std::array<double, 3>;

/// The front's pieces in one square leaf: up to two segments.
int frontSegments(const CellPolynomial<2>& p, const Point2& c, double h, Point2 (&ends)[4])
{
  const double r = 0.5 * h;
  const Point2 corner[4] = { { c[0] - r, c[1] - r }, { c[0] + r, c[1] - r }, { c[0] + r, c[1] + r },
    { c[0] - r, c[1] + r } };
  double v[4];
  int negative = 0;
  for (int k = 0; k < 4; ++k)
  {
    v[k] = p.eval(corner[k]);
    negative += v[k] < 0.0 ? 1 : 0;
  }
  if (negative == 0 || negative == 4)
  {
    return 0;
  }
  Point2 cut[4];
  bool crossed[4];
  int count = 0;
  for (int k = 0; k < 4; ++k)
  {
    const int l = (k + 1) % 4;
    crossed[k] = (v[k] < 0.0) != (v[l] < 0.0);
    if (crossed[k])
    {
      const double t = v[k] / (v[k] - v[l]);
      cut[k] = { corner[k][0] + t * (corner[l][0] - corner[k][0]), corner[k][1] + t * (corner[l][1] - corner[k][1]) };
      ++count;
    }
  }
  if (count == 2)
  {
    int m = 0;
    for (int k = 0; k < 4; ++k)
    {
      if (crossed[k])
      {
        ends[m++] = cut[k];
      }
    }
    return 1;
  }
  // A saddle: corners 0 and 2 share a sign; the centre's sign says which corners the front cuts off.
  const bool centreWithFirst = (p.value() < 0.0) == (v[0] < 0.0);
  const int order[2][4] = { { 3, 0, 1, 2 }, { 0, 1, 2, 3 } };
  for (int m = 0; m < 4; ++m)
  {
    ends[m] = cut[order[centreWithFirst ? 1 : 0][m]];
  }
  return 2;
}

/// (4.29) in one leaf: sum of |d|^e along its segments, for e = p and q.
bool leafIntegrals(const CellPolynomial<2>& phi, const CellPolynomial<2>& d, const Point2& c, double h, double,
  double p, double q, double& first, double& second)
{
  Point2 ends[4];
  const int segments = frontSegments(phi, c, h, ends);
  for (int s = 0; s < segments; ++s)
  {
    const Point2& a = ends[2 * s];
    const Point2& b = ends[2 * s + 1];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const double da = std::fabs(d.eval(a)), db = std::fabs(d.eval(b));
    first += 0.5 * (std::pow(da, p) + std::pow(db, p)) * length;
    second += 0.5 * (std::pow(da, q) + std::pow(db, q)) * length;
  }
  return segments > 0;
}

/// (4.30) in one leaf: its subcells near the zero set of phi's polynomial.
/// The subcells have the finest leaves' size (R per finest leaf), so the
/// shell |p| < sqrt(3)/2 h' is the same everywhere: a coarse leaf flat at
/// +-gamma never falls in it, as it would with subcells of its own size.
bool leafIntegrals(const CellPolynomial<3>& phi, const CellPolynomial<3>& d, const Point3& c, double h, double finest,
  double p, double q, double& first, double& second)
{
  constexpr int R = 5;
  const std::int64_t n = R * std::max<std::int64_t>(1, std::llround(h / finest));
  const double sub = h / n, near = 0.5 * std::sqrt(3.0) * sub, weight = sub * sub / std::sqrt(3.0);
  // Q1 takes its extremes on the cube at the corners: skip leaves whose corners all lie beyond `near` on one side.
  int above = 0, below = 0;
  for (int k = 0; k < 8; ++k)
  {
    const double v =
      phi.eval({ c[0] + (k & 1 ? 0.5 : -0.5) * h, c[1] + (k & 2 ? 0.5 : -0.5) * h, c[2] + (k & 4 ? 0.5 : -0.5) * h });
    above += v >= near ? 1 : 0;
    below += v <= -near ? 1 : 0;
  }
  if (above == 8 || below == 8)
  {
    return false;
  }
  bool front = false;
  for (std::int64_t k = 0; k < n * n * n; ++k)
  {
    const Point3 x{ c[0] - 0.5 * h + (k % n + 0.5) * sub, c[1] - 0.5 * h + (k / n % n + 0.5) * sub,
      c[2] - 0.5 * h + (k / (n * n) + 0.5) * sub };
    if (std::fabs(phi.eval(x)) < near)
    {
      const double dx = std::fabs(d.eval(x));
      first += std::pow(dx, p) * weight;
      second += std::pow(dx, q) * weight;
      front = true;
    }
  }
  return front;
}

} // namespace

template <int D>
CellEnergy cellEnergy(const LeafGraph<D>& graph, const std::vector<CellPolynomial<D>>& phi,
  const std::vector<CellPolynomial<D>>& distance, double finest, double p, double q, const Context& ctx,
  const Communicator& comm)
{
  const size_t n = static_cast<size_t>(graph.Owned);
  std::vector<std::array<double, 2>> integrals(n, { 0.0, 0.0 });
  std::vector<char> front(n, 0);
  ctx.parallelFor(0, graph.Owned,
    [&](Index b, Index e)
    {
      for (Index i = b; i < e; ++i)
      {
        const size_t k = static_cast<size_t>(i);
        front[k] = leafIntegrals(
          phi[k], distance[k], graph.Centres[k], graph.Sizes[k], finest, p, q, integrals[k][0], integrals[k][1]);
      }
    });
  // The front leaves' integrals of every rank in the global Morton order
  // (rank order): the sums of one rank, on any number of ranks and threads.
  std::vector<std::array<double, 2>> local;
  for (size_t k = 0; k < n; ++k)
  {
    if (front[k])
    {
      local.push_back(integrals[k]);
    }
  }
  const std::vector<std::array<double, 2>> all = comm.size() > 1 ? comm.allGatherV(local) : std::move(local);
  CellEnergy energy;
  for (const auto& leaf : all)
  {
    energy.Integral += leaf[0];
    energy.SecondIntegral += leaf[1];
  }
  energy.FrontLeaves = static_cast<Index>(all.size());
  return energy;
}

template <int D>
CellCloudErrors cellCloudErrors(const std::vector<std::array<double, D>>& points, const std::vector<int>& leafOfPoint,
  const std::vector<CellPolynomial<D>>& phi, int owned, double far, const Communicator& comm)
{
  // |p_k(Q)| at the points in this rank's leaves, added in the points' order over all ranks.
  struct PointError
  {
    std::int64_t Point;
    double Error;
  };
  std::vector<PointError> local;
  for (size_t k = 0; k < points.size(); ++k)
  {
    const int leaf = leafOfPoint[k];
    if (leaf >= 0 && leaf < owned)
    {
      local.push_back({ static_cast<std::int64_t>(k), std::fabs(phi[static_cast<size_t>(leaf)].eval(points[k])) });
    }
  }
  std::vector<double> error(points.size(), 0.0);
  for (const auto& at : comm.size() > 1 ? comm.allGatherV(local) : std::move(local))
  {
    error[static_cast<size_t>(at.Point)] = at.Error;
  }
  double sum = 0.0, farCount = 0.0;
  for (const double e : error)
  {
    sum += e;
    farCount += e > far ? 1.0 : 0.0;
  }
  CellCloudErrors result;
  if (!points.empty())
  {
    result.Mean = sum / static_cast<double>(points.size());
    result.FarFraction = farCount / static_cast<double>(points.size());
  }
  return result;
}

template CellEnergy cellEnergy(const LeafGraph<2>&, const std::vector<CellPolynomial<2>>&,
  const std::vector<CellPolynomial<2>>&, double, double, double, const Context&, const Communicator&);
template CellEnergy cellEnergy(const LeafGraph<3>&, const std::vector<CellPolynomial<3>>&,
  const std::vector<CellPolynomial<3>>&, double, double, double, const Context&, const Communicator&);
template CellCloudErrors cellCloudErrors<2>(const std::vector<std::array<double, 2>>&, const std::vector<int>&,
  const std::vector<CellPolynomial<2>>&, int, double, const Communicator&);
template CellCloudErrors cellCloudErrors<3>(const std::vector<std::array<double, 3>>&, const std::vector<int>&,
  const std::vector<CellPolynomial<3>>&, int, double, const Communicator&);

} // namespace p4est
} // namespace sltk
