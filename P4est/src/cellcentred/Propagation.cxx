// SPDX-License-Identifier: GPL-2.0-or-later
#include "Propagation.h"

#include <algorithm>
#include <cmath>

namespace sltk
{
namespace p4est
{

template <int D>
void resetPropagation(int leaves, Propagation<D>& state)
{
  state.Distance.assign(static_cast<size_t>(leaves), std::numeric_limits<double>::infinity());
  state.Reference.assign(static_cast<size_t>(leaves), {});
  state.Fixed.assign(static_cast<size_t>(leaves), 0);
}

namespace
{

/// On several ranks: the ghosts' states from their owners; the ghosts whose
/// distance fell (lowered on their owner in the last step, or D^0 there)
/// are appended to `front`. Returns whether any rank's front is not empty.
/// Its cost is the ghosts' and the mirrors', not the leaves'.
template <int D>
bool exchangeGhosts(const LeafGraph<D>& graph, const CellTree<D>& tree, Propagation<D>& state, std::vector<int>& front,
  std::vector<double>& before)
{
  const size_t owned = static_cast<size_t>(graph.Owned), n = static_cast<size_t>(graph.size());
  before.assign(state.Distance.begin() + static_cast<std::ptrdiff_t>(owned), state.Distance.end());
  tree.syncGhosts(state.Distance);
  tree.syncGhosts(state.Reference);
  for (size_t i = owned; i < n; ++i)
  {
    if (state.Distance[i] < before[i - owned])
    {
      front.push_back(static_cast<int>(i));
    }
  }
  return tree.communicator().anyRank(!front.empty());
}

} // namespace

template <int D>
int propagate(
  const LeafGraph<D>& graph, std::vector<int> front, Propagation<D>& state, double limit, const CellTree<D>* tree)
{
  struct Candidate
  {
    int Leaf;
    double Distance;
    std::array<double, D> Reference;
  };
  const bool distributed = tree && tree->communicator().size() > 1;
  const auto inGlobalOrder = [&graph](int a, int b)
  { return graph.GlobalIds[static_cast<size_t>(a)] < graph.GlobalIds[static_cast<size_t>(b)]; };
  std::vector<Candidate> candidates;
  std::vector<int> next;
  std::vector<double> before;
  int steps = 0;
  bool going = distributed ? exchangeGhosts(graph, *tree, state, front, before) : !front.empty();
  while (going)
  {
    ++steps;
    std::sort(front.begin(), front.end(), inGlobalOrder);
    candidates.clear();
    for (const int k : front)
    {
      const auto& hat = state.Reference[static_cast<size_t>(k)];
      for (int m = graph.Offsets[static_cast<size_t>(k)]; m < graph.Offsets[static_cast<size_t>(k) + 1]; ++m)
      {
        const int j = graph.Neighbours[static_cast<size_t>(m)];
        if (state.Fixed[static_cast<size_t>(j)] || j >= graph.Owned) // a ghost is lowered by its owner
        {
          continue;
        }
        const double q = pointDistance<D>(graph.Centres[static_cast<size_t>(j)], hat); // (5.8)
        if (q < state.Distance[static_cast<size_t>(j)] && q < limit)
        {
          candidates.push_back({ j, q, hat });
        }
      }
    }
    // (5.9): the lowered leaves, each with its smallest candidate (ties: the first found).
    next.clear();
    for (const Candidate& c : candidates)
    {
      if (c.Distance < state.Distance[static_cast<size_t>(c.Leaf)])
      {
        state.Distance[static_cast<size_t>(c.Leaf)] = c.Distance;
        state.Reference[static_cast<size_t>(c.Leaf)] = c.Reference;
        next.push_back(c.Leaf);
      }
    }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    front.swap(next);
    going = distributed ? exchangeGhosts(graph, *tree, state, front, before) : !front.empty();
  }
  return steps;
}

template void resetPropagation(int, Propagation<2>&);
template void resetPropagation(int, Propagation<3>&);
template int propagate(const LeafGraph<2>&, std::vector<int>, Propagation<2>&, double, const CellTree<2>*);
template int propagate(const LeafGraph<3>&, std::vector<int>, Propagation<3>&, double, const CellTree<3>*);

} // namespace p4est
} // namespace sltk
