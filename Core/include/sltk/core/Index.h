// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Index.h
/// The signed 64-bit index of nodes, points, steps and loop ranges in Core.

#include <cstdint>

namespace sltk
{

using Index = std::int64_t;

/// floor(v) as an Index without a call of the library's floor: exact for finite v
/// in the Index range. The inner loops that locate feet and points call it; a
/// library call there makes the compiler spill every live floating-point register
/// around it (they are all caller-saved), which cost more than the rounding.
inline Index floorToIndex(double v)
{
  const Index truncated = static_cast<Index>(v);
  return truncated - (v < static_cast<double>(truncated) ? 1 : 0);
}

} // namespace sltk
