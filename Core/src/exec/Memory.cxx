// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/Memory.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

namespace sltk
{

namespace
{
/// Value in kB of the line "<key>: <value> kB" in a /proc file, in bytes.
std::uint64_t procField(const char* file, const std::string& key)
{
  std::ifstream in(file);
  std::string name;
  while (in >> name)
  {
    if (name == key + ":")
    {
      std::uint64_t kb = 0;
      in >> kb;
      return kb * 1024u;
    }
    in.ignore(1 << 16, '\n');
  }
  return 0;
}
} // namespace

std::uint64_t availableMemoryBytes()
{
  return procField("/proc/meminfo", "MemAvailable");
}

std::uint64_t peakResidentBytes()
{
  return procField("/proc/self/status", "VmHWM");
}

int ranksSharingThisMachine(int ranks)
{
  ranks = std::max(1, ranks);
  for (const char* name : { "OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS" })
  {
    if (const char* local = std::getenv(name))
    {
      const int count = std::atoi(local);
      if (count > 0)
      {
        return std::min(count, ranks);
      }
    }
  }
  return ranks;
}

} // namespace sltk
