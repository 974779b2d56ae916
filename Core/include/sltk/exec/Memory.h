// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Memory.h
/// Memory facts used to refuse absurd grid sizes before allocating them.

#include <cstdint>

namespace sltk
{

/// Bytes the system can still give (Linux: MemAvailable of /proc/meminfo);
/// 0 when unknown.
std::uint64_t availableMemoryBytes();

/// Peak resident set size of this process in bytes (Linux: VmHWM); 0 when unknown.
std::uint64_t peakResidentBytes();

} // namespace sltk
