// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file DisjointSets.h
/// The root of a disjoint-set forest stored as parent ids (a root is its own
/// parent), with path halving: every node on the way points to its grandparent.
/// Shared by the grouping of points (recon/PointClusters.h) and the automatic
/// K_P's bottleneck (recon/CloudInitialData.cxx).

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

} // namespace sltk
