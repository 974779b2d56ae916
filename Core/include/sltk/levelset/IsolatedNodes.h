// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file IsolatedNodes.h
/// Single nodes whose sign differs from that of all their 2D axis neighbours:
/// a piece of the zero level set smaller than one cell, which the contour
/// draws as a closed octahedron of 8 triangles around the node (a separate
/// piece, or a bubble inside the body). Such a piece is below the grid's
/// resolution (one node cannot carry a feature the grid resolves), and the
/// thesis's least-squares Q1 (5.5), which is discontinuous between
/// neighbouring nodes' fits, leaves some where the front is thin
/// (Documentation/Numerics.md, "Single-node specks"). A run's result gives
/// such a node the mean of its axis neighbours, whose sign they all share,
/// so the speck joins its surroundings; every other node is left alone.
///
/// Decisions read the values before any change (the result does not depend on
/// the order the nodes are visited in, nor on how they are shared between
/// ranks); nodes on the grid's boundary, and nodes with a neighbour not
/// known here (NaN), are left alone.

#include "sltk/grid/GridField.h"
#include "sltk/levelset/NarrowBand.h"

#include <array>
#include <cmath>
#include <vector>

namespace sltk
{

/// A node's new value when it is isolated: `at(a, side)` returns its
/// neighbour's value along axis a (side -1 or +1). Returns true, with
/// `merged` the mean of the 2D neighbours, when every neighbour is known and
/// on the other side of zero (phi < 0 inside) than `value`.
template <int D, class At>
bool isolatedNodeValue(double value, At&& at, double& merged)
{
  const bool inside = value < 0.0;
  double sum = 0.0;
  for (int a = 0; a < D; ++a)
  {
    for (const int side : { -1, 1 })
    {
      const double n = at(a, side);
      if (std::isnan(n) || (n < 0.0) == inside)
      {
        return false;
      }
      sum += n;
    }
  }
  merged = sum / (2.0 * D);
  return true;
}

/// Whether node i has both axis neighbours along every axis within a grid of `dims` nodes.
template <int D>
bool hasAllAxisNeighbours(const std::array<Index, D>& i, const std::array<Index, D>& dims)
{
  for (int a = 0; a < D; ++a)
  {
    if (i[a] <= 0 || i[a] + 1 >= dims[a])
    {
      return false;
    }
  }
  return true;
}

/// A node to change and its new value.
struct NodeChange
{
  Index Node = 0; ///< the storage's index of the node
  double Value = 0.0;
};

/// The isolated nodes among `nodes` (interior linear indices of phi, as
/// NarrowBand.h's lists), appended to `changes`; nodes on phi's boundary are
/// skipped (on a slab, the window's first and last rows are the grid's
/// boundary or ghost rows, which hold no listed node).
template <int D>
void findIsolatedNodes(const GridField<D>& phi, const NodeList& nodes, std::vector<NodeChange>& changes)
{
  const auto& dims = phi.spec().Dims;
  const auto& strides = phi.strides();
  for (const Index k : nodes)
  {
    const std::array<Index, D> i = phi.nodeIndex(k);
    if (!hasAllAxisNeighbours<D>(i, dims))
    {
      continue;
    }
    const double* p = phi.pointer(i);
    double merged = 0.0;
    if (isolatedNodeValue<D>(
          *p, [&](int a, int side) { return p[side * strides[a]]; }, merged))
    {
      changes.push_back({ k, merged });
    }
  }
}

/// Writes `changes` (findIsolatedNodes) into phi.
template <int D>
void applyNodeChanges(GridField<D>& phi, const std::vector<NodeChange>& changes)
{
  for (const NodeChange& c : changes)
  {
    phi(phi.nodeIndex(c.Node)) = c.Value;
  }
}

} // namespace sltk
