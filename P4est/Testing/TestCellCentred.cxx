// SPDX-License-Identifier: GPL-2.0-or-later
// The thesis's cell-centred scheme (CellCentredReconstruction.h) and its
// parts: the quadtree's neighbours and point location, the least-squares Q1
// (5.5), the propagation (5.8)-(5.9), the closest-point reinitialisation
// (5.2.4), and the chapter 5 circle end to end. Serial (each rank of the
// 2-rank run computes the same alone).
#include "CellCentredCases.h"

#include "cellcentred/CellEnergy.h"
#include "cellcentred/CellTree.h"
#include "cellcentred/ClosestPointReinit.h"
#include "cellcentred/LeastSquaresQ1.h"
#include "cellcentred/Propagation.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/p4est/CellCentredReconstruction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using namespace sltk::p4est;
using Point = std::array<double, 2>;
using Graph = LeafGraph<2>;
using Data = CellData<2>;

/// A balanced tree over [-1, 1]^D refined to `level` around the sphere of radius 0.6.
template <int D>
std::unique_ptr<CellTree<D>> sphereTree(int level, LeafGraph<D>& graph, std::vector<CellData<D>*>& data)
{
  std::unique_ptr<CellTree<D>> forest;
  std::array<double, D> origin;
  origin.fill(-1.0);
  EXPECT_TRUE(CellTree<D>::create(sltk::serialCommunicator(), origin, 2.0, 2, forest).isOk());
  forest->refine(level,
    [](const CellData<D>&, const std::array<double, D>& c, double h)
    {
      double r = 0.0;
      for (int a = 0; a < D; ++a)
      {
        r += c[a] * c[a];
      }
      return std::fabs(std::sqrt(r) - 0.6) <= std::sqrt(double(D)) * h;
    });
  forest->balance();
  forest->leaves(graph, data);
  return forest;
}

std::unique_ptr<CellTree<2>> circleTree(Graph& graph, std::vector<Data*>& data)
{
  return sphereTree<2>(7, graph, data);
}

/// Whether two leaves share a face, an edge or a corner.
template <int D>
bool touches(const LeafGraph<D>& g, int i, int j)
{
  const double reach = 0.5 * (g.Sizes[size_t(i)] + g.Sizes[size_t(j)]);
  bool contact = false;
  for (int a = 0; a < D; ++a)
  {
    const double d = std::fabs(g.Centres[size_t(i)][a] - g.Centres[size_t(j)][a]);
    if (d > reach * (1 + 1e-12))
    {
      return false;
    }
    contact = contact || std::fabs(d - reach) < 1e-12;
  }
  return contact;
}

template <int D>
void checkNeighbours(int level, int mostNeighbours)
{
  LeafGraph<D> g;
  std::vector<CellData<D>*> data;
  auto forest = sphereTree<D>(level, g, data);
  ASSERT_GT(g.size(), 1000);
  int levels[2] = { 99, 0 };
  for (int i = 0; i < g.size(); ++i)
  {
    levels[0] = std::min(levels[0], g.Levels[size_t(i)]);
    levels[1] = std::max(levels[1], g.Levels[size_t(i)]);
    const int count = g.Offsets[size_t(i) + 1] - g.Offsets[size_t(i)];
    EXPECT_GE(count, (1 << D) - 1);
    EXPECT_LE(count, mostNeighbours);
    for (int k = g.Offsets[size_t(i)]; k < g.Offsets[size_t(i) + 1]; ++k)
    {
      const int j = g.Neighbours[size_t(k)];
      ASSERT_NE(j, i);
      EXPECT_TRUE(touches<D>(g, i, j)) << i << " " << j;
      EXPECT_LE(std::abs(g.Levels[size_t(i)] - g.Levels[size_t(j)]), 1) << "2:1 balance";
      const auto begin = g.Neighbours.begin() + g.Offsets[size_t(j)];
      const auto end = g.Neighbours.begin() + g.Offsets[size_t(j) + 1];
      EXPECT_NE(std::find(begin, end, i), end) << "symmetric";
    }
  }
  EXPECT_LE(levels[0], 3) << "coarse far from the sphere";
  EXPECT_EQ(levels[1], level);
  // Every touching leaf is listed: a sample checked by brute force.
  for (int i = 0; i < g.size(); i += 37)
  {
    int touching = 0;
    for (int j = 0; j < g.size(); ++j)
    {
      touching += j != i && touches<D>(g, i, j) ? 1 : 0;
    }
    EXPECT_EQ(touching, g.Offsets[size_t(i) + 1] - g.Offsets[size_t(i)]) << "leaf " << i;
  }
}

/// (5.5) is exact on multilinear data, whatever the leaves' sizes around.
template <int D>
void checkMultilinearFit(int level)
{
  LeafGraph<D> g;
  std::vector<CellData<D>*> data;
  auto forest = sphereTree<D>(level, g, data);
  const auto f = [](const std::array<double, D>& x)
  {
    double v = 1.0 + 0.5 * x[0] * x[1];
    for (int a = 0; a < D; ++a)
    {
      v += (a + 2.0) * x[a];
    }
    return D == 3 ? v - 0.7 * x[0] * x[D - 1] + 0.3 * x[0] * x[1] * x[D - 1] + 0.2 * x[1] * x[D - 1] : v;
  };
  std::vector<double> values(size_t(g.size()));
  for (int i = 0; i < g.size(); ++i)
  {
    values[size_t(i)] = f(g.Centres[size_t(i)]);
  }
  std::vector<CellPolynomial<D>> p;
  fitLeastSquaresQ1(g, values, sltk::Context{}, p);
  for (int i = 0; i < g.size(); ++i)
  {
    for (const double o : { 0.3, -0.4, 0.0 })
    {
      std::array<double, D> x = g.Centres[size_t(i)];
      for (int a = 0; a < D; ++a)
      {
        x[a] += (a % 2 ? -o : o) * g.Sizes[size_t(i)];
      }
      EXPECT_NEAR(p[size_t(i)].eval(x), f(x), 1e-12);
    }
  }
}

/// The integrals of d^p and d^q, d = x_1 + 2, over the circle or sphere of
/// radius r = 0.6 (phi its signed distance, cut at +-4 cells: the coarse
/// leaves far from it are flat and must not count): in 2D 4 pi r and
/// pi r^3 + 8 pi r, in 3D 8 pi r^2 and 4/3 pi r^4 + 16 pi r^2.
template <int D>
CellEnergy frontIntegrals(int level, double p, double q)
{
  LeafGraph<D> g;
  std::vector<CellData<D>*> data;
  auto forest = sphereTree<D>(level, g, data);
  const double dx = 2.0 / (1 << level), gamma = 4.0 * dx;
  std::vector<double> phi(size_t(g.size())), d(size_t(g.size()));
  for (int i = 0; i < g.size(); ++i)
  {
    double r = 0.0;
    for (int a = 0; a < D; ++a)
    {
      r += g.Centres[size_t(i)][a] * g.Centres[size_t(i)][a];
    }
    phi[size_t(i)] = std::clamp(std::sqrt(r) - 0.6, -gamma, gamma);
    d[size_t(i)] = g.Centres[size_t(i)][0] + 2.0; // linear: its polynomials are exact
  }
  std::vector<CellPolynomial<D>> phiFit, dFit;
  fitLeastSquaresQ1(g, phi, sltk::Context{}, phiFit);
  fitLeastSquaresQ1(g, d, sltk::Context{}, dFit);
  return cellEnergy<D>(g, phiFit, dFit, dx, p, q, sltk::Context{}, sltk::serialCommunicator());
}

/// A linear field and its exact polynomial on every leaf of `data`.
template <int D>
double linearField(const std::array<double, D>& x)
{
  double v = 0.25;
  for (int a = 0; a < D; ++a)
  {
    v += (0.5 + a) * x[a];
  }
  return v;
}

template <int D>
void setLinearData(const LeafGraph<D>& g, const std::vector<CellData<D>*>& data)
{
  for (int i = 0; i < g.size(); ++i)
  {
    CellData<D>& q = *data[size_t(i)];
    q.Phi = linearField<D>(g.Centres[size_t(i)]);
    q.Polynomial = CellPolynomial<D>{};
    q.Polynomial.Centre = g.Centres[size_t(i)];
    q.Polynomial.C[0] = q.Phi;
    for (int a = 0; a < D; ++a)
    {
      q.Polynomial.C[size_t(1) << a] = 0.5 + a;
    }
  }
}

/// One corner of the cube refined to the deepest level: the keys, the
/// neighbours and the location hold there, and every new leaf (refinement
/// and balance) took its parent's polynomial's value at its centre (5.2.2).
template <int D>
void checkDeepestLevel()
{
  std::unique_ptr<CellTree<D>> tree;
  std::array<double, D> origin;
  origin.fill(-1.0);
  ASSERT_TRUE(CellTree<D>::create(sltk::serialCommunicator(), origin, 2.0, 1, tree).isOk());
  LeafGraph<D> g;
  std::vector<CellData<D>*> data;
  tree->leaves(g, data);
  setLinearData<D>(g, data);
  std::array<double, D> target;
  target.fill(0.3);
  tree->refine(CellTree<D>::deepestLevel(),
    [&target](const CellData<D>&, const std::array<double, D>& c, double h)
    {
      bool inside = true;
      for (int a = 0; a < D; ++a)
      {
        inside = inside && std::fabs(target[a] - c[a]) <= 0.5 * h;
      }
      return inside;
    });
  tree->balance();
  tree->leaves(g, data);
  int deepest = 0;
  for (int i = 0; i < g.size(); ++i)
  {
    deepest = std::max(deepest, g.Levels[size_t(i)]);
    EXPECT_NEAR(data[size_t(i)]->Phi, linearField<D>(g.Centres[size_t(i)]), 1e-14) << "leaf " << i;
  }
  EXPECT_EQ(deepest, CellTree<D>::deepestLevel());
  std::vector<int> leaf;
  tree->locate(g.Centres, leaf);
  for (int i = 0; i < g.size(); ++i)
  {
    ASSERT_EQ(leaf[size_t(i)], i);
    int touching = 0;
    for (int j = 0; j < g.size(); ++j)
    {
      touching += j != i && touches<D>(g, i, j) ? 1 : 0;
    }
    EXPECT_EQ(touching, g.Offsets[size_t(i) + 1] - g.Offsets[size_t(i)]) << "leaf " << i;
  }
}

} // namespace

TEST(CellCentred, EnergyIntegratesOverTheFrontLeafByLeaf)
{
  const double pi = std::acos(-1.0), r = 0.6;
  const CellEnergy two = frontIntegrals<2>(7, 1.0, 2.0);
  const CellEnergy three = frontIntegrals<3>(5, 1.0, 2.0);
  // Measured: within 1.3e-4 (2D) and 2.0e-3 (3D) of the exact integrals.
  EXPECT_NEAR(two.Integral / (4.0 * pi * r), 1.0, 1e-3);
  EXPECT_NEAR(two.SecondIntegral / (pi * r * r * r + 8.0 * pi * r), 1.0, 1e-3);
  EXPECT_NEAR(three.Integral / (8.0 * pi * r * r), 1.0, 1e-2);
  EXPECT_NEAR(three.SecondIntegral / (4.0 / 3.0 * pi * r * r * r * r + 16.0 * pi * r * r), 1.0, 1e-2);
  EXPECT_GT(two.FrontLeaves, 0);
}

TEST(CellCentred, NeighboursAreTheTouchingLeavesUnderTwoToOneBalance)
{
  checkNeighbours<2>(7, 12);
  checkNeighbours<3>(5, 56);
}

TEST(CellCentred, LeastSquaresQ1ReproducesMultilinearData)
{
  checkMultilinearFit<2>(7);
  checkMultilinearFit<3>(5);
}

TEST(CellCentred, DeepestLevelsKeepTheirKeysNeighboursAndInheritedValues)
{
  checkDeepestLevel<2>();
  checkDeepestLevel<3>();
}

TEST(CellCentred, CoarseningKeepsTheBalanceSoTheTreeSettles)
{
  // The circle's band refined to level 7, then flat everywhere but on the
  // right (x > 0.4): the flat families coarsen as far as the 2:1 balance
  // allows next to the right's finest leaves, and balancing after them
  // changes nothing (no family is coarsened only to be refined again, which
  // would also defeat the reuse of an unchanged tree).
  Graph g;
  std::vector<Data*> data;
  auto tree = circleTree(g, data);
  const long refined = tree->leafCount();
  for (int i = 0; i < g.size(); ++i)
  {
    *data[size_t(i)] = Data{};
    data[size_t(i)]->Phi = g.Centres[size_t(i)][0] > 0.4 ? 0.5 : 1.0; // 1: flat, slope 0
  }
  const auto flat = [](const Data* const family[4])
  {
    for (int k = 0; k < 4; ++k)
    {
      if (family[k]->Phi != 1.0)
      {
        return false;
      }
    }
    return true;
  };
  EXPECT_GT(tree->coarsen(2, flat), 100);
  const long coarsened = tree->leafCount();
  EXPECT_LT(coarsened, refined / 2);
  const long revision = tree->revision();
  tree->balance();
  EXPECT_EQ(tree->leafCount(), coarsened) << "the coarsening kept the 2:1 balance";
  EXPECT_EQ(tree->revision(), revision);
  tree->leaves(g, data);
  int finest = 0;
  for (int i = 0; i < g.size(); ++i)
  {
    finest = std::max(finest, g.Levels[size_t(i)]);
    for (int k = g.Offsets[size_t(i)]; k < g.Offsets[size_t(i) + 1]; ++k)
    {
      EXPECT_LE(std::abs(g.Levels[size_t(i)] - g.Levels[size_t(g.Neighbours[size_t(k)])]), 1);
    }
  }
  EXPECT_EQ(finest, 7) << "the right's leaves stayed";
}

TEST(CellCentred, LocatesPointsInTheirLeaf)
{
  Graph g;
  std::vector<Data*> data;
  auto forest = circleTree(g, data);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::vector<Point> points(2000);
  for (auto& p : points)
  {
    p = { u(random), u(random) };
  }
  points.push_back({ 1.0, 1.0 }); // the square's far corner
  std::vector<int> leaf;
  forest->locate(points, leaf);
  for (size_t k = 0; k < points.size(); ++k)
  {
    ASSERT_GE(leaf[k], 0);
    const auto& c = g.Centres[size_t(leaf[k])];
    const double half = 0.5 * g.Sizes[size_t(leaf[k])];
    for (int a = 0; a < 2; ++a)
    {
      const double inside = std::clamp(points[k][a], -1.0, 1.0); // outside: the nearest leaf
      EXPECT_LE(std::fabs(inside - c[a]), half * (1 + 1e-12)) << k;
    }
  }
}

TEST(CellCentred, PropagationGivesTheDistanceToOnePointExactly)
{
  Graph g;
  std::vector<Data*> data;
  auto forest = circleTree(g, data);
  const Point source{ 0.31, -0.17 };
  std::vector<int> leaf;
  forest->locate({ source }, leaf);
  Propagation<2> state;
  resetPropagation(g.size(), state);
  state.Distance[size_t(leaf[0])] =
    std::hypot(g.Centres[size_t(leaf[0])][0] - source[0], g.Centres[size_t(leaf[0])][1] - source[1]);
  state.Reference[size_t(leaf[0])] = source;
  const int steps = propagate(g, { leaf[0] }, state);
  EXPECT_GT(steps, 10);
  for (int i = 0; i < g.size(); ++i)
  {
    const auto& x = g.Centres[size_t(i)];
    EXPECT_DOUBLE_EQ(state.Distance[size_t(i)], std::hypot(x[0] - source[0], x[1] - source[1]));
  }
}

TEST(CellCentred, PropagationFromTheCirclesPointsNearlyGivesTheNearestDistance)
{
  Graph g;
  std::vector<Data*> data;
  auto forest = circleTree(g, data);
  const auto cloud = sltk::circleCloud(64, 0.6);
  std::vector<Point> points(cloud.Points.begin(), cloud.Points.end());
  std::vector<int> leaf;
  forest->locate(points, leaf);
  Propagation<2> state;
  resetPropagation(g.size(), state);
  std::vector<int> front;
  for (size_t k = 0; k < points.size(); ++k)
  {
    const size_t i = size_t(leaf[k]);
    const double q = std::hypot(g.Centres[i][0] - points[k][0], g.Centres[i][1] - points[k][1]);
    if (q < state.Distance[i])
    {
      state.Distance[i] = q;
      state.Reference[i] = points[k];
    }
    front.push_back(int(i));
  }
  propagate(g, front, state);
  double largest = 0.0;
  int exact = 0;
  for (int i = 0; i < g.size(); ++i)
  {
    double nearest = 1e300;
    for (const auto& q : points)
    {
      nearest = std::min(nearest, std::hypot(g.Centres[size_t(i)][0] - q[0], g.Centres[size_t(i)][1] - q[1]));
    }
    const double error = state.Distance[size_t(i)] - nearest;
    EXPECT_GE(error, -1e-15) << "the propagated distance is to a cloud point: never below the nearest";
    largest = std::max(largest, error);
    exact += error < 1e-15 ? 1 : 0;
  }
  std::printf("propagation: %d of %d leaves exact, largest excess %.3g\n", exact, g.size(), largest);
  // (5.8)-(5.9) carry a neighbour's point, not always the nearest (measured:
  // 2,152 of 2,176 exact, 0.21 cells at most on this tree).
  EXPECT_GE(exact, g.size() * 98 / 100);
  EXPECT_LT(largest, 0.5 * 2.0 / 128.0);
}

TEST(CellCentred, ClosestPointsReinitialiseToTheSignedDistance)
{
  Graph g;
  std::vector<Data*> data;
  auto forest = circleTree(g, data);
  const double r = 0.6, dx = 2.0 / 128.0, gamma = 4.0 * dx;
  std::vector<double> phi(size_t(g.size()));
  for (int i = 0; i < g.size(); ++i)
  {
    const auto& x = g.Centres[size_t(i)];
    phi[size_t(i)] = 3.0 * (std::hypot(x[0], x[1]) - r) * (1.0 + x[0] * x[0]); // not a distance
  }
  std::vector<CellPolynomial<2>> p;
  fitLeastSquaresQ1(g, phi, sltk::Context{}, p);
  const ClosestPointReport report = reinitialiseByClosestPoints(g, p, gamma, sltk::Context{}, phi);
  EXPECT_GT(report.FrontLeaves, 200);
  EXPECT_GT(report.Seeds, 3 * report.FrontLeaves);
  EXPECT_EQ(report.SeedFallbacks, 0);
  double largest = 0.0;
  for (int i = 0; i < g.size(); ++i)
  {
    const auto& x = g.Centres[size_t(i)];
    const double exact = std::hypot(x[0], x[1]) - r;
    if (std::fabs(exact) < gamma - 2 * dx)
    {
      largest = std::max(largest, std::fabs(phi[size_t(i)] - exact));
    }
    else if (std::fabs(exact) > gamma + 2 * dx)
    {
      EXPECT_EQ(std::fabs(phi[size_t(i)]), gamma) << "cut at gamma (1.49)";
    }
    EXPECT_EQ(phi[size_t(i)] < 0.0, exact < 0.0);
  }
  // Measured: 0.07 cells, at leaves 1.5-2 cells inside that the propagation
  // reached with a neighbour's closest point.
  std::printf("closest points: largest error %.3g cells in the band\n", largest / dx);
  EXPECT_LT(largest, 0.15 * dx);
}

TEST(CellCentred, ReconstructsTheThesisCircle)
{
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  const sltk::ReconstructionOptions& options = plan.Options;
  CellCentredOptions cc;
  cc.FirstCellSize = 2.0 / 64.0; // (5.10)-(5.11): L0 = 6 for this cloud
  CellCentredResult<2> result;
  ASSERT_TRUE(reconstructCellCentred(plan, cc, sltk::Context{}, result).isOk());
  ASSERT_EQ(result.Runs.size(), 3u);
  for (const auto& run : result.Runs)
  {
    EXPECT_GE(run.Iterations, options.MinIterations);
    EXPECT_LT(run.Iterations, options.MaxIterations) << "(4.33) stops every run";
  }
  const auto& last = result.Runs.back();
  EXPECT_EQ(last.Level, 9);
  EXPECT_LT(last.CloudError, 2.4e-3) << "the thesis: 1.20e-3";
  EXPECT_NEAR(last.Energy, 7.1e-2, 0.5e-2) << "the exact circle's E_2";
  double largest = 0.0;
  for (const auto& leaf : result.Leaves)
  {
    const double exact = std::hypot(leaf.Centre[0], leaf.Centre[1]) - 1.0;
    if (std::fabs(exact) < 2.0 * last.CellSize)
    {
      largest = std::max(largest, std::fabs(leaf.Phi - exact));
      EXPECT_EQ(leaf.Size, last.CellSize) << "the band is refined to the finest level";
    }
  }
  EXPECT_LT(largest, last.CellSize) << "measured: 0.57 cells (the curve sags between the 64 points)";
  EXPECT_LT(result.Leaves.size(), 262144u / 20) << "under 5% of the uniform grid";
}

TEST(CellCentred, ReconstructsASphereInThreeDimensions)
{
  // The 642-point icosphere, two runs on an octree (levels 5 and 6 of a cube
  // of edge 4): the 3D step (four feet), reinitialisation and energy in the loop.
  sltk::ReconstructionPlan<3> plan;
  ASSERT_TRUE(planIcosphere(plan).isOk());
  const sltk::ReconstructionOptions& options = plan.Options;
  CellCentredOptions cc;
  cc.FirstCellSize = 1.0 / 8.0;
  CellCentredResult<3> result;
  ASSERT_TRUE(reconstructCellCentred(plan, cc, sltk::Context{}, result).isOk());
  ASSERT_EQ(result.Runs.size(), 2u);
  for (const auto& run : result.Runs)
  {
    EXPECT_LT(run.Iterations, options.MaxIterations);
    EXPECT_LT(run.TreeChanges, run.Iterations + 1);
  }
  EXPECT_LT(result.Runs[1].CloudError, result.Runs[0].CloudError) << "the finer run is closer to the points";
  const double dx = result.Runs[1].CellSize;
  EXPECT_LT(result.Runs[1].CloudError, 0.25 * dx);
  double largest = 0.0;
  for (const auto& leaf : result.Leaves)
  {
    const double exact =
      std::sqrt(leaf.Centre[0] * leaf.Centre[0] + leaf.Centre[1] * leaf.Centre[1] + leaf.Centre[2] * leaf.Centre[2]) -
      1.0;
    if (std::fabs(exact) < 2.0 * dx)
    {
      largest = std::max(largest, std::fabs(leaf.Phi - exact));
    }
  }
  // Measured: iterations 18 and 22, Err_P 1.12e-2 then 6.65e-3, 0.51 cells.
  EXPECT_LT(largest, dx);
}

TEST(CellCentred, RefusesWithoutACircleToStartFrom)
{
  sltk::ReconstructionOptions options = sltk::ReconstructionOptions::thesis();
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(sltk::planReconstruction(sltk::circleCloud(64), options, sltk::Context{}, plan).isOk());
  CellCentredOptions cc;
  cc.FirstCellSize = 2.0 / 64.0;
  CellCentredResult<2> result;
  const sltk::Status s = reconstructCellCentred(plan, cc, sltk::Context{}, result);
  EXPECT_EQ(s.code(), sltk::StatusCode::InvalidArgument);
  EXPECT_NE(s.message().find("BoundingSphere"), std::string::npos) << s.message();
  cc.FirstCellSize = 0.0;
  EXPECT_EQ(reconstructCellCentred(plan, cc, sltk::Context{}, result).code(), sltk::StatusCode::InvalidArgument);
}

TEST(CellCentred, RefusesATreeBeyondTheMemoryBudget)
{
  sltk::ReconstructionPlan<2> plan;
  ASSERT_TRUE(planThesisCircle(plan).isOk());
  CellCentredOptions cc;
  cc.FirstCellSize = 2.0 / 64.0;
  cc.MemoryBudget = 3000 * static_cast<std::uint64_t>(CellCentredBytesPerLeaf); // run 1 holds 2,416 leaves
  CellCentredResult<2> result;
  const sltk::Status s = reconstructCellCentred(plan, cc, sltk::Context{}, result);
  EXPECT_EQ(s.code(), sltk::StatusCode::OutOfMemory);
  EXPECT_NE(s.message().find("run 2 (level 8)"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("FirstCellSize"), std::string::npos) << s.message();
}
