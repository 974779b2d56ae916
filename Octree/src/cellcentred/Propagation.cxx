// SPDX-License-Identifier: GPL-2.0-or-later
#include "Propagation.h"

#include <algorithm>
#include <cmath>

namespace sltk
{
namespace octree
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

/// A leaf's state as the ghost exchange carries it.
template <int D>
struct Reached
{
  double Distance;
  std::array<double, D> Reference;
};

/// On several ranks: the ghosts' states from their owners; the ghosts whose
/// distance fell (lowered on their owner in the last step, or D^0 there)
/// are appended to `front`. Returns whether any rank's front is not empty.
template <int D>
bool exchangeGhosts(const LeafGraph<D>& graph, const CellTree<D>& tree, Propagation<D>& state, std::vector<int>& front)
{
  const size_t n = static_cast<size_t>(graph.size());
  std::vector<Reached<D>> reached(n);
  for (size_t i = 0; i < n; ++i)
  {
    reached[i] = { state.Distance[i], state.Reference[i] };
  }
  tree.syncGhosts(reached);
  for (size_t i = static_cast<size_t>(graph.Owned); i < n; ++i)
  {
    if (reached[i].Distance < state.Distance[i])
    {
      state.Distance[i] = reached[i].Distance;
      state.Reference[i] = reached[i].Reference;
      front.push_back(static_cast<int>(i));
    }
  }
  return tree.communicator().allReduce(std::int64_t(front.empty() ? 0 : 1), ReduceOp::Max) > 0;
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
  int steps = 0;
  bool going = distributed ? exchangeGhosts(graph, *tree, state, front) : !front.empty();
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
    going = distributed ? exchangeGhosts(graph, *tree, state, front) : !front.empty();
  }
  return steps;
}

template void resetPropagation(int, Propagation<2>&);
template void resetPropagation(int, Propagation<3>&);
template int propagate(const LeafGraph<2>&, std::vector<int>, Propagation<2>&, double, const CellTree<2>*);
template int propagate(const LeafGraph<3>&, std::vector<int>, Propagation<3>&, double, const CellTree<3>*);

} // namespace octree
} // namespace sltk
