// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RankParts.h
/// Buffers grouped by destination rank for one personalised all-to-all
/// (Communicator::allToAllRecords): each rank's records counted first, then
/// placed once (PointOwners.cxx, CloudThinning.cxx).

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

} // namespace sltk
