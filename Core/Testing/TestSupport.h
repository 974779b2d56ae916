// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TestSupport.h
/// Small helpers shared by the Core tests: node coordinates, nodal sampling
/// of functions of a point, |x|^2, and the check that an interpolator returns
/// the nodal values. Grids are sltk::uniformBox (sltk/grid/GridSpec.h),
/// fields with ghost values filled by the boundary policy are
/// sltk::sampleField (sltk/grid/SampleField.h), synthetic clouds and exact
/// distances are in sltk/cloud/SyntheticClouds.h.

#include "sltk/grid/GridField.h"
#include "sltk/interp/Interpolator.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <random>

namespace sltktest
{

/// The coordinates of node i.
template <int D>
std::array<double, D> nodeCoordinates(const sltk::GridSpec<D>& g, const std::array<sltk::Index, D>& i)
{
  std::array<double, D> x{};
  for (int a = 0; a < D; ++a)
  {
    x[a] = g.coordinate(a, i[a]);
  }
  return x;
}

/// The coordinates of the node of flat index k of a field.
template <int D, class T>
std::array<double, D> nodeCoordinates(const sltk::GridField<D, T>& f, sltk::Index k)
{
  return nodeCoordinates<D>(f.spec(), f.nodeIndex(k));
}

/// A field with `ghost` layers holding f(x) at the nodes, f taking the node's
/// std::array<double, D> coordinates; the ghost values are left at zero.
template <int D, class F>
sltk::GridField<D> sampleNodes(const sltk::GridSpec<D>& g, int ghost, F f)
{
  sltk::GridField<D> u(g, ghost);
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    u(i) = f(nodeCoordinates<D>(g, i));
  }
  return u;
}

/// |x|^2, x given by its D coordinates.
template <int D>
double squaredNorm(const double* x)
{
  double r = 0.0;
  for (int a = 0; a < D; ++a)
  {
    r += x[a] * x[a];
  }
  return r;
}

/// Expects interpolation at every node of g to return the nodal value of u to
/// the last bit (EXPECT_EQ, no tolerance); u is sampled on g.
template <int D, class Interp>
void expectNodalValuesExactly(Interp& interp, const sltk::GridSpec<D>& g, const sltk::GridField<D>& u)
{
  for (sltk::Index k = 0; k < g.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    const auto x = nodeCoordinates<D>(g, i);
    EXPECT_EQ(sltk::interpolate(interp, g, x.data()), u(i)) << "node " << k;
  }
}

/// The lanes of `lanes` (Weno3Lanes, LsqQ1Lanes: eval() and the portable
/// evalAny()) against `expected(location)` one foot at a time, bit for bit, at
/// `trials` random groups of feet on g: a quarter of the groups on nodes, a
/// quarter half-way between two nodes, the rest over and beyond the box.
/// Returns the number of lanes that differ.
template <int D, class Lanes, class Expected>
int lanesMismatches(const sltk::GridSpec<D>& g, const Lanes& lanes, Expected expected, int trials)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.3, 1.5);
  std::uniform_int_distribution<int> node(0, static_cast<int>(g.Dims[0]) - 2);
  constexpr int Count = Lanes::Count;
  int mismatches = 0;
  for (int trial = 0; trial < trials; ++trial)
  {
    std::array<sltk::CellLocation<D>, Count> at;
    for (int l = 0; l < Count; ++l)
    {
      double x[D];
      for (int a = 0; a < D; ++a)
      {
        const int k = node(rng);
        x[a] = trial % 4 == 0 ? g.coordinate(a, k)
                              : (trial % 4 == 1 ? 0.5 * (g.coordinate(a, k) + g.coordinate(a, k + 1)) : u(rng));
      }
      at[l] = sltk::locate(g, x);
    }
    double values[Count], portable[Count];
    lanes.eval(at, values);
    lanes.evalAny(at, portable);
    for (int l = 0; l < Count; ++l)
    {
      const double e = expected(at[l]);
      mismatches += std::memcmp(&e, &values[l], sizeof(double)) == 0 ? 0 : 1;
      mismatches += std::memcmp(&e, &portable[l], sizeof(double)) == 0 ? 0 : 1;
    }
  }
  return mismatches;
}

} // namespace sltktest
