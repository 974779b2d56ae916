// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudFileShares.h"

#include <algorithm>

namespace sltk
{

namespace
{
/// The '\n' bytes in [from, to) of `in` (none when the range is empty).
std::int64_t countNewlines(std::istream& in, std::int64_t from, std::int64_t to)
{
  std::int64_t newlines = 0;
  if (from >= to)
  {
    return 0;
  }
  in.clear();
  in.seekg(from);
  std::vector<char> block(std::size_t(1) << 20);
  for (std::int64_t left = to - from; left > 0 && in;)
  {
    const std::int64_t want = std::min<std::int64_t>(left, static_cast<std::int64_t>(block.size()));
    in.read(block.data(), want);
    const std::streamsize got = in.gcount();
    newlines += std::count(block.data(), block.data() + got, '\n');
    left -= got;
    if (got < want)
    {
      break;
    }
  }
  return newlines;
}
} // namespace

FileShare shareOf(std::int64_t begin, std::int64_t end, int rank, int ranks)
{
  const std::int64_t items = std::max<std::int64_t>(0, end - begin);
  return { begin + items * rank / ranks, begin + items * (rank + 1) / ranks };
}

std::int64_t firstLineStart(std::istream& in, FileShare share, std::int64_t origin)
{
  if (share.Begin >= share.End || share.Begin <= origin)
  {
    return share.Begin >= share.End ? share.End : share.Begin;
  }
  in.clear();
  in.seekg(share.Begin - 1);
  std::int64_t at = share.Begin - 1;
  for (int c = in.get(); c != std::istream::traits_type::eof(); c = in.get())
  {
    ++at;
    if (c == '\n')
    {
      return std::min(at, share.End);
    }
  }
  return share.End;
}

std::int64_t countLineStarts(std::istream& in, FileShare share, std::int64_t origin)
{
  if (share.Begin >= share.End)
  {
    return 0;
  }
  // A line starts at q when q is the origin or follows a '\n' at q - 1.
  const std::int64_t from = std::max(share.Begin - 1, origin);
  return (share.Begin <= origin ? 1 : 0) + countNewlines(in, from, share.End - 1);
}

} // namespace sltk
