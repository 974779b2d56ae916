// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RankParts.h
/// Buffers grouped by destination rank for one personalised all-to-all
/// (Communicator::allToAllRecords): each rank's records counted first, then
/// placed once (groupByRank: PointOwners.cxx, CloudThinning.cxx).

#include <cassert>
#include <cstdint>
#include <vector>

namespace sltk
{

/// Where each rank's part starts in a buffer grouped by rank (`counts` elements each), and its end.
inline std::vector<size_t> startsOf(const std::vector<std::int64_t>& counts)
{
  std::vector<size_t> first(counts.size() + 1, 0);
  for (size_t r = 0; r < counts.size(); ++r)
  {
    first[r + 1] = first[r] + static_cast<size_t>(counts[r]);
  }
  return first;
}

/// A buffer grouped by destination rank for one personalised all-to-all, counted then placed
/// once. `visit(emit)` calls emit(r, make) for every record bound for rank r, in the order the
/// records are to go, and emits the same records in both of its calls: the first only counts
/// them (`counts`, one per rank), the second stores make(slot) at the record's slot in the
/// buffer (make may note the slot elsewhere). The records for rank `kept` (when it is >= 0) go
/// to `keptRecords` instead, slot the index there, and stay out of the exchange: counts[kept]
/// is 0, so the records a rank keeps (a share read near its own slab, the cells it averages)
/// are not copied through the buffers.
template <class Record, class Visit>
std::vector<Record> groupByRank(size_t ranks, std::vector<std::int64_t>& counts, const Visit& visit, int kept = -1,
  std::vector<Record>* keptRecords = nullptr)
{
  assert(kept < 0 || (keptRecords && static_cast<size_t>(kept) < ranks));
  counts.assign(ranks, 0);
  visit([&](size_t r, const auto&) { ++counts[r]; });
  if (kept >= 0)
  {
    keptRecords->clear();
    keptRecords->reserve(static_cast<size_t>(counts[static_cast<size_t>(kept)]));
    counts[static_cast<size_t>(kept)] = 0;
  }
  std::vector<size_t> next = startsOf(counts);
  std::vector<Record> send(next[ranks]);
  visit(
    [&](size_t r, const auto& make)
    {
      if (static_cast<int>(r) == kept)
      {
        keptRecords->push_back(make(keptRecords->size()));
      }
      else
      {
        const size_t slot = next[r]++;
        send[slot] = make(slot);
      }
    });
  return send;
}

} // namespace sltk
