// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/ExactDistanceCache.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace sltk
{

namespace
{
/// Nodes grouped by boxes of (2^BoxBits)^D nodes, each box's distances found at
/// once (PointLocator::nearestDistances: bit for bit the per-node queries);
/// a box with fewer than MinBatch nodes asks one query a node. Per thread.
template <int D>
struct BoxBatch
{
  static constexpr Index BoxBits = 2; ///< boxes of 4^D nodes: spread at most 1.5 sqrt(D) dx
  static constexpr size_t MinBatch = 8;
  /// A ball of more candidates asks one query a node. Run 1's boxes lie up to
  /// K_P h_P from a cloud of cells of 2-3 h_P: on the merged scans and the dragon
  /// their balls pass 1024 points, and the box at once still pays (run 1's band
  /// phase 0.80 -> 0.44 s and 0.87 -> 0.51 s against 1024; 16384 no better).
  static constexpr std::int64_t MaxCandidates = 4096;

  std::vector<std::pair<Index, Index>> Keyed; ///< (box, storage slot)
  std::vector<std::array<double, D>> Positions;
  std::vector<double> Distances;
  std::vector<std::int64_t> Candidates;

  /// values[slot] = the distance to the cloud at every storage slot of `slots`.
  void compute(const std::vector<Index>& slots, const std::array<Index, D>& padded, const GridField<D>& dist,
    const PointLocator<D>& locator, double* values)
  {
    this->Keyed.clear();
    for (const Index slot : slots)
    {
      Index rest = slot, key = 0, stride = 1;
      for (int a = 0; a < D; ++a)
      {
        key += ((rest % padded[a]) >> BoxBits) * stride;
        stride *= (padded[a] >> BoxBits) + 1;
        rest /= padded[a];
      }
      this->Keyed.emplace_back(key, slot);
    }
    std::sort(this->Keyed.begin(), this->Keyed.end());
    for (size_t first = 0; first < this->Keyed.size();)
    {
      size_t last = first + 1;
      while (last < this->Keyed.size() && this->Keyed[last].first == this->Keyed[first].first)
      {
        ++last;
      }
      const size_t n = last - first;
      this->Positions.resize(n);
      for (size_t i = 0; i < n; ++i)
      {
        this->Positions[i] = position(this->Keyed[first + i].second, padded, dist);
      }
      if (n < MinBatch)
      {
        for (size_t i = 0; i < n; ++i)
        {
          values[this->Keyed[first + i].second] = locator.nearest(this->Positions[i]).Distance;
        }
      }
      else
      {
        this->Distances.resize(n);
        locator.nearestDistances(this->Positions.data(), static_cast<std::int64_t>(n), this->Distances.data(),
          this->Candidates, MaxCandidates);
        for (size_t i = 0; i < n; ++i)
        {
          values[this->Keyed[first + i].second] = this->Distances[i];
        }
      }
      first = last;
    }
  }

  /// The coordinates of a storage slot (ghosts included in `padded`).
  static std::array<double, D> position(Index slot, const std::array<Index, D>& padded, const GridField<D>& dist)
  {
    std::array<double, D> x;
    for (int a = 0; a < D; ++a)
    {
      x[a] = dist.spec().coordinate(a, slot % padded[a] - dist.ghost());
      slot /= padded[a];
    }
    return x;
  }
};
} // namespace

template <int D>
Index ExactDistanceCache<D>::ensure(const NodeList& band, const Context& ctx, GridField<D>& dist)
{
  // Stencil of a band node: the corners {0,1}^D of its cell and its face neighbours -e_a.
  std::array<Index, (1 << D) + D> stencil{};
  std::array<std::array<Index, D>, (1 << D) + D> shift{};
  int n = 0;
  for (int c = 0; c < (1 << D); ++c)
  {
    for (int a = 0; a < D; ++a)
    {
      shift[n][a] = (c >> a) & 1;
    }
    ++n;
  }
  for (int a = 0; a < D; ++a)
  {
    shift[n][a] = -1;
    ++n;
  }
  for (int s = 0; s < n; ++s)
  {
    stencil[s] = dist.offset(shift[s]) - dist.offset({});
  }
  const auto& spec = dist.spec();
  // Both threads mark: a slot's flag is claimed by one atomic fetch_or, so each
  // slot is computed once, by the chunk that claimed it first (which one does
  // not change its value, nor the count). A node whose stencil was made exact
  // at an earlier call (most of the band: it moves a few nodes an iteration)
  // is passed over on its own flag.
  const Index size = static_cast<Index>(band.size());
  const Index grain = std::max<Index>(1024, (size + 63) / 64);
  const Index chunks = (size + grain - 1) / grain;
  std::vector<std::vector<Index>> pending(static_cast<size_t>(chunks));
  ctx.parallelFor(
    0, size,
    [&](Index b, Index e)
    {
      std::vector<Index>& mine = pending[static_cast<size_t>(b / grain)];
      Index previous = -2, lineEnd = 0, base = 0;
      for (Index p = b; p < e; ++p)
      {
        const Index k = band[static_cast<size_t>(p)];
        if (k == previous + 1 && k < lineEnd)
        {
          ++base; // the next node of an x line is the next storage slot (no division)
        }
        else
        {
          const auto i = dist.nodeIndex(k);
          base = dist.offset(i);
          lineEnd = k - i[0] + spec.Dims[0];
        }
        previous = k;
        std::atomic<std::uint8_t>& node = this->Exact[base];
        if (node.load(std::memory_order_relaxed) & StencilExact)
        {
          continue;
        }
        for (int s = 0; s < n; ++s)
        {
          const Index slot = base + stencil[s];
          std::atomic<std::uint8_t>& exact = this->Exact[slot];
          if (!(exact.load(std::memory_order_relaxed) & SlotExact) &&
            !(exact.fetch_or(SlotExact, std::memory_order_relaxed) & SlotExact))
          {
            mine.push_back(slot);
          }
        }
        node.fetch_or(StencilExact, std::memory_order_relaxed);
      }
    },
    grain);
  std::array<Index, D> padded{};
  for (int a = 0; a < D; ++a)
  {
    padded[a] = spec.Dims[a] + 2 * dist.ghost();
  }
  double* values = dist.storage().data();
  ctx.parallelFor(
    0, chunks,
    [&](Index b, Index e)
    {
      BoxBatch<D> batch;
      for (Index c = b; c < e; ++c)
      {
        batch.compute(pending[static_cast<size_t>(c)], padded, dist, *this->Locator, values);
      }
    },
    1);
  if (this->Comm && this->Comm->size() > 1 && std::isfinite(this->Reach))
  {
    this->settleBeyondReach(pending, padded, ctx, dist);
  }
  Index computed = 0;
  for (const std::vector<Index>& mine : pending)
  {
    computed += static_cast<Index>(mine.size());
  }
  return computed;
}

template <int D>
void ExactDistanceCache<D>::settleBeyondReach(const std::vector<std::vector<Index>>& pending,
  const std::array<Index, D>& padded, const Context& ctx, GridField<D>& dist) const
{
  double* values = dist.storage().data();
  std::vector<Index> far;
  std::vector<std::array<double, D>> mine;
  for (const std::vector<Index>& slots : pending)
  {
    for (const Index slot : slots)
    {
      if (values[slot] > this->Reach)
      {
        far.push_back(slot);
        mine.push_back(BoxBatch<D>::position(slot, padded, dist));
      }
    }
  }
  // Every rank's far nodes, each measured against every rank's points: the
  // least is the whole cloud's distance (each point is held by some rank).
  std::vector<std::int64_t> counts;
  const std::vector<std::array<double, D>> all = this->Comm->allGatherV(mine, &counts);
  if (all.empty())
  {
    return;
  }
  std::vector<double> nearest(all.size());
  ctx.parallelFor(0, static_cast<Index>(all.size()),
    [&](Index b, Index e)
    {
      for (Index k = b; k < e; ++k)
      {
        nearest[static_cast<size_t>(k)] = this->Locator->nearest(all[static_cast<size_t>(k)]).Distance;
      }
    });
  this->Comm->allReduce(nearest.data(), nearest.size(), ReduceOp::Min);
  size_t first = 0;
  for (int r = 0; r < this->Comm->rank(); ++r)
  {
    first += static_cast<size_t>(counts[static_cast<size_t>(r)]);
  }
  for (size_t k = 0; k < far.size(); ++k)
  {
    values[far[k]] = nearest[first + k];
  }
}

template class ExactDistanceCache<2>;
template class ExactDistanceCache<3>;

} // namespace sltk
