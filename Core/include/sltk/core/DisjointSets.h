// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file DisjointSets.h
/// The root of a disjoint-set forest stored as parent ids (a root is its own
/// parent), with path halving: every node on the way points to its grandparent.
/// Shared by the grouping of points (recon/PointClusters.h), the automatic K_P's
/// bottleneck (recon/CloudInitialData.cxx), the result's pieces
/// (recon/InsideComponents.h) and the CLI's surface pieces.

#include <cstddef>
#include <vector>

namespace sltk
{

template <class Id>
Id findRoot(std::vector<Id>& parent, Id x)
{
  while (parent[static_cast<size_t>(x)] != x)
  {
    parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    x = parent[static_cast<size_t>(x)];
  }
  return x;
}

/// A forest of `n` singletons: every id its own root.
template <class Id>
std::vector<Id> singletonForest(size_t n)
{
  std::vector<Id> parent(n);
  for (size_t k = 0; k < n; ++k)
  {
    parent[k] = static_cast<Id>(k);
  }
  return parent;
}

/// Joins the sets of a and b under b's root (b's root found first, as the
/// assignment parent[findRoot(a)] = findRoot(b) orders it).
template <class Id>
void unite(std::vector<Id>& parent, Id a, Id b)
{
  const Id rootB = findRoot(parent, b);
  const Id rootA = findRoot(parent, a);
  parent[static_cast<size_t>(rootA)] = rootB;
}

} // namespace sltk
