// SPDX-License-Identifier: BSD-3-Clause
// The ranks' shares of a cloud file (sltk/cloud/CloudFileShares.h): the
// shares tile the range in rank order, and every line of a text belongs to
// exactly one share, the one that holds its first byte, for any rank count.
#include "sltk/cloud/CloudFileShares.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace
{
/// The offsets at which lines start in `text` from `origin` on (origin, then after each '\n').
std::vector<std::int64_t> lineStarts(const std::string& text, std::int64_t origin)
{
  std::vector<std::int64_t> starts;
  for (std::int64_t q = origin; q < static_cast<std::int64_t>(text.size()); ++q)
  {
    if (q == origin || text[static_cast<size_t>(q - 1)] == '\n')
    {
      starts.push_back(q);
    }
  }
  return starts;
}

/// The line starts each share reads: from firstLineStart, every line start before the share's end.
std::vector<std::int64_t> startsRead(const std::string& text, sltk::FileShare share, std::int64_t origin)
{
  std::istringstream in(text);
  std::vector<std::int64_t> read;
  for (std::int64_t q : lineStarts(text, origin))
  {
    if (q >= sltk::firstLineStart(in, share, origin) && q < share.End)
    {
      read.push_back(q);
    }
  }
  return read;
}
} // namespace

TEST(CloudFileShares, SharesTileTheRangeInRankOrder)
{
  for (std::int64_t items : { 0, 1, 5, 7, 1000003 })
  {
    for (int ranks = 1; ranks <= 9; ++ranks)
    {
      std::int64_t next = 10;
      for (int r = 0; r < ranks; ++r)
      {
        const sltk::FileShare share = sltk::shareOf(10, 10 + items, r, ranks);
        EXPECT_EQ(share.Begin, next) << items << " items, rank " << r << " of " << ranks;
        EXPECT_LE(share.End - share.Begin, items / ranks + 1);
        EXPECT_GE(share.End - share.Begin, items / ranks);
        next = share.End;
      }
      EXPECT_EQ(next, 10 + items);
    }
  }
}

TEST(CloudFileShares, EveryLineIsReadByTheShareOfItsFirstByte)
{
  // CRLF ends, a blank line, a long line, a final line without '\n', and a prologue before `origin`.
  const std::string text = "x y z\n# c\n1 2 3\r\n\r\n4 5 6\n7 8 9 10 11 12 13 14 15 16 17 18\n\n0.5 0.25 1e-3";
  const std::int64_t origin = 10; // the first point's line
  const std::vector<std::int64_t> all = lineStarts(text, origin);
  ASSERT_EQ(all.size(), 6u);
  for (int ranks = 1; ranks <= static_cast<int>(text.size()) + 2; ++ranks)
  {
    std::vector<std::int64_t> joined;
    std::int64_t counted = 0;
    for (int r = 0; r < ranks; ++r)
    {
      const sltk::FileShare share = sltk::shareOf(origin, static_cast<std::int64_t>(text.size()), r, ranks);
      const std::vector<std::int64_t> mine = startsRead(text, share, origin);
      for (std::int64_t q : mine)
      {
        EXPECT_TRUE(q >= share.Begin && q < share.End) << "line at " << q << " read by rank " << r << " of " << ranks;
      }
      joined.insert(joined.end(), mine.begin(), mine.end());
      std::istringstream in(text);
      EXPECT_EQ(sltk::countLineStarts(in, share, origin), static_cast<std::int64_t>(mine.size()))
        << "rank " << r << " of " << ranks;
      counted += static_cast<std::int64_t>(mine.size());
    }
    EXPECT_EQ(joined, all) << ranks << " ranks: every line once, in file order";
    EXPECT_EQ(counted, static_cast<std::int64_t>(all.size()));
  }
}

TEST(CloudFileShares, AShareInsideOneLineReadsNothing)
{
  const std::string text = "1 2 3\n4444444444 5 6\n7 8 9\n";
  std::istringstream in(text);
  const sltk::FileShare inside{ 8, 12 }; // within "4444444444 5 6"
  EXPECT_EQ(sltk::firstLineStart(in, inside, 0), inside.End);
  EXPECT_EQ(sltk::countLineStarts(in, inside, 0), 0);
  const sltk::FileShare atLineStart{ 6, 8 }; // the byte after a '\n': that line is this share's
  EXPECT_EQ(sltk::firstLineStart(in, atLineStart, 0), 6);
  EXPECT_EQ(sltk::countLineStarts(in, atLineStart, 0), 1);
}
