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

/// How many of `ranks` MPI ranks run on this machine and share its memory and
/// cores: the launcher's count (OpenMPI's OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's
/// MPI_LOCALNRANKS) when it gives one, at most `ranks`; else all `ranks`.
int ranksSharingThisMachine(int ranks);

} // namespace sltk
