// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file Propagation.h
/// The propagation of distances through the tree (thesis 5.2.5, (5.8)-(5.9)):
/// leaves of D^0 hold a distance q_k to a reference point xhat_k; at each
/// step every neighbour x_j of D^m takes min over the neighbours x_k in D^m
/// of |x_j - xhat_k| when that is below its q_j, and the leaves so lowered
/// form D^{m+1}, until D is empty. Each step reads D^m's references as they
/// were at its start (a Jacobi sweep), as (5.8) is written, and D^m is taken
/// in the global Morton order (ties go to the first leaf of that order).
/// On several ranks each rank lowers its own leaves; after each step the
/// ghosts' distances and references come from their owners, those lowered
/// join D^{m+1}, and the propagation ends when D is empty on every rank: the
/// same distances and references as on one rank, the ghosts' included.

#include "CellTree.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sltk
{
namespace p4est
{

/// |a - b|, the distance of (5.8).
template <int D>
double pointDistance(const std::array<double, D>& a, const std::array<double, D>& b)
{
  double s = 0.0;
  for (int k = 0; k < D; ++k)
  {
    s += (a[k] - b[k]) * (a[k] - b[k]);
  }
  return std::sqrt(s);
}

template <int D>
struct Propagation
{
  std::vector<double> Distance;                 ///< q per leaf (+infinity where nothing arrived)
  std::vector<std::array<double, D>> Reference; ///< xhat per leaf
  std::vector<char> Fixed;                      ///< leaves the propagation may not change (the reinitialised D^0)
};

/// Sizes `state` for `leaves` leaves, every distance +infinity, nothing fixed.
template <int D>
void resetPropagation(int leaves, Propagation<D>& state);

/// Runs (5.8)-(5.9) from `front` (D^0: this rank's leaves; the ghosts of
/// D^0 are found from their owners). Distances at or beyond `limit` are
/// not propagated (the leaf keeps +infinity): the reinitialisation needs
/// them only below gamma. `tree` (the tree of `graph`) is needed on several
/// ranks, and then the call is collective. Returns the number of steps.
template <int D>
int propagate(const LeafGraph<D>& graph, std::vector<int> front, Propagation<D>& state,
  double limit = std::numeric_limits<double>::infinity(), const CellTree<D>* tree = nullptr);

} // namespace p4est
} // namespace sltk
