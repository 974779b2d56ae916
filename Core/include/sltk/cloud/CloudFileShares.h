// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudFileShares.h
/// The ranks' shares of a cloud file, read in parallel (Documentation/Distributed.md,
/// "Reading the cloud"): a range of items (the bytes of a text cloud, the vertex
/// records of a binary PLY) cut into one contiguous share per rank, in rank order.
/// A text share is cut at line ends: every line belongs to exactly one rank, the
/// one whose share holds its first byte.

#include <array>
#include <cstdint>
#include <istream>
#include <vector>

namespace sltk
{

/// The items [Begin, End) of one rank.
struct FileShare
{
  std::int64_t Begin = 0;
  std::int64_t End = 0;
};

/// Rank `rank`'s share of [begin, end): the shares of ranks 0..ranks-1 tile it
/// in rank order, each of floor or ceil of (end - begin) / ranks items.
FileShare shareOf(std::int64_t begin, std::int64_t end, int rank, int ranks);

/// The first line that starts in `share` of the text in `in` whose lines start
/// at `origin` (the first line of the shared range) and after each '\n': its
/// offset, or share.End when no line starts in the share (the line that holds
/// share.Begin began in an earlier share, which reads it whole).
std::int64_t firstLineStart(std::istream& in, FileShare share, std::int64_t origin);

/// The number of lines that start in `share` (origin as firstLineStart's), from
/// the '\n' bytes alone: the line numbers of the later shares start after them.
std::int64_t countLineStarts(std::istream& in, FileShare share, std::int64_t origin);

/// The points of this rank's share of a cloud file, in file order, and the
/// points of the whole file (every rank's count added).
struct CloudShare
{
  std::vector<std::array<double, 3>> Points;
  std::int64_t Total = 0;
};

} // namespace sltk
