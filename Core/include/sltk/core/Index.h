// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Index.h
/// The signed 64-bit index of nodes, points, steps and loop ranges in Core.

#include <cstdint>

namespace sltk
{

using Index = std::int64_t;

} // namespace sltk
