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

template <int D>
int propagate(const LeafGraph<D>& graph, std::vector<int> front, Propagation<D>& state, double limit)
{
  struct Candidate
  {
    int Leaf;
    double Distance;
    std::array<double, D> Reference;
  };
  std::vector<Candidate> candidates;
  std::vector<int> next;
  int steps = 0;
  while (!front.empty())
  {
    ++steps;
    candidates.clear();
    for (const int k : front)
    {
      const auto& hat = state.Reference[static_cast<size_t>(k)];
      for (int m = graph.Offsets[static_cast<size_t>(k)]; m < graph.Offsets[static_cast<size_t>(k) + 1]; ++m)
      {
        const int j = graph.Neighbours[static_cast<size_t>(m)];
        if (state.Fixed[static_cast<size_t>(j)])
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
  }
  return steps;
}

template void resetPropagation(int, Propagation<2>&);
template void resetPropagation(int, Propagation<3>&);
template int propagate(const LeafGraph<2>&, std::vector<int>, Propagation<2>&, double);
template int propagate(const LeafGraph<3>&, std::vector<int>, Propagation<3>&, double);

} // namespace octree
} // namespace sltk
