// SPDX-License-Identifier: BSD-3-Clause
// Cloud files read in shares (sltk/cloud/TextCloudFile.h, PlyCloudFile.h),
// serially and under `mpiexec -n 2`: the shares gathered in rank order are the
// one-rank cloud, in its order, and a bad line in any share fails every rank
// with the one-rank message.
#include "MpiWorld.h"

#include "sltk/cloud/PlyCloudFile.h"
#include "sltk/cloud/TextCloudFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
using Points = std::vector<std::array<double, 3>>;

/// A file of `bytes` that rank 0 writes and every rank then reads.
std::string sharedFile(const sltk::Communicator& comm, const std::string& name, const std::string& bytes)
{
  std::int64_t id = static_cast<std::int64_t>(::getpid());
  comm.broadcast(&id, sizeof(id), 0);
  const std::string path =
    (std::filesystem::temp_directory_path() / ("sltk_cloud_files_" + std::to_string(id) + "_" + name)).string();
  if (comm.rank() == 0)
  {
    std::ofstream(path, std::ios::binary) << bytes;
  }
  comm.barrier();
  return path;
}

/// Removes a sharedFile once every rank has read it.
void removeShared(const sltk::Communicator& comm, const std::string& path)
{
  comm.barrier();
  if (comm.rank() == 0)
  {
    std::remove(path.c_str());
  }
}

/// The one-rank read of `path` on this rank, and the ranks' shares of it gathered in rank order.
void readBoth(const std::string& path, const sltk::Communicator& comm, sltk::Status& serial, Points& whole,
  sltk::Status& split, Points& gathered, std::int64_t& total)
{
  sltk::CloudShare one, share;
  serial = sltk::readTextCloudShare(path, sltk::serialCommunicator(), one);
  whole = one.Points;
  split = sltk::readTextCloudShare(path, comm, share);
  gathered = comm.allGatherV(share.Points);
  total = share.Total;
}

/// The text cloud `text` read in shares is the one-rank cloud `expected`.
void expectSameCloud(const std::string& name, const std::string& text, const Points& expected)
{
  auto comm = world();
  const std::string path = sharedFile(*comm, name, text);
  sltk::Status serial, split;
  Points whole, gathered;
  std::int64_t total = -1;
  readBoth(path, *comm, serial, whole, split, gathered, total);
  EXPECT_TRUE(serial.isOk()) << serial.message();
  EXPECT_TRUE(split.isOk()) << split.message();
  EXPECT_EQ(whole, expected) << name;
  EXPECT_EQ(gathered, whole) << name << " on " << comm->size() << " ranks";
  EXPECT_EQ(total, static_cast<std::int64_t>(whole.size()));
  removeShared(*comm, path);
}

/// `count` points on lines "i 0.5*i -i", each ended by `end`.
std::string linesOf(int count, const std::string& end, Points& points)
{
  std::string text;
  for (int i = 0; i < count; ++i)
  {
    text += std::to_string(i) + " " + std::to_string(0.5 * i) + " " + std::to_string(-i) + end;
    points.push_back({ double(i), 0.5 * i, double(-i) });
  }
  return text;
}
} // namespace

TEST(CloudFiles, CrlfCommentsAndAHeaderGiveTheOneRankCloud)
{
  Points expected;
  std::string text = "x,y,z\r\n# scanner A\r\n\r\n" + linesOf(40, "\r\n", expected);
  text += "// a comment among the points\r\n\r\n" + linesOf(3, "\r\n", expected);
  expectSameCloud("crlf.xyz", text, expected);
}

TEST(CloudFiles, AFinalLineWithoutNewlineIsRead)
{
  Points expected;
  std::string text = linesOf(25, "\n", expected) + "7,8;9";
  expected.push_back({ 7, 8, 9 });
  expectSameCloud("final.csv", text, expected);
}

TEST(CloudFiles, FewerLinesThanRanks)
{
  expectSameCloud("one.xyz", "1 2 3", { { 1, 2, 3 } });
  expectSameCloud("comments.xyz", "# no points\n", {});
  Points counted;
  expectSameCloud("counted.pts", "2\n" + linesOf(2, "\n", counted), counted);
}

TEST(CloudFiles, ABadLineInTheLastSharesFailsEveryRankWithTheOneRankMessage)
{
  auto comm = world();
  Points unused;
  // Line 90 of 100 is past the middle: rank 1's share on two ranks (the last rank's on any count).
  std::string text = linesOf(89, "\n", unused) + "1 2 3abc\n" + linesOf(10, "\n", unused);
  const std::string path = sharedFile(*comm, "bad.xyz", text);
  sltk::Status serial, split;
  Points whole, gathered;
  std::int64_t total = 0;
  readBoth(path, *comm, serial, whole, split, gathered, total);
  EXPECT_EQ(serial.message(), path + ":90: '3abc' is not a number");
  EXPECT_FALSE(split.isOk());
  EXPECT_EQ(split.message(), serial.message()) << "rank " << comm->rank() << " of " << comm->size();
  EXPECT_TRUE(gathered.empty() || !split.isOk());
  // Two bad lines, one per half: the first is reported, as one rank reports it.
  text = linesOf(10, "\n", unused) + "1 2\n" + linesOf(78, "\n", unused) + "1 2 3abc\n" + linesOf(10, "\n", unused);
  const std::string two = sharedFile(*comm, "bad2.xyz", text);
  readBoth(two, *comm, serial, whole, split, gathered, total);
  EXPECT_EQ(serial.message(), two + ":11: expected three coordinates per line (x y z), got 2");
  EXPECT_EQ(split.message(), serial.message());
  removeShared(*comm, path);
  removeShared(*comm, two);
}

TEST(CloudFiles, ACountThatDisagreesFailsEveryRank)
{
  auto comm = world();
  Points unused;
  const std::string path = sharedFile(*comm, "short.pts", "30\n" + linesOf(29, "\n", unused));
  sltk::CloudShare share;
  const sltk::Status split = sltk::readTextCloudShare(path, *comm, share);
  EXPECT_EQ(split.message(),
    path +
      ": its first line announces 30 points, it holds 29: is the file cut short (or "
      "two scans joined)?");
  removeShared(*comm, path);
}

namespace
{
/// A binary PLY of the vertex properties `header` (after "element vertex N") and the records `records`.
std::string plyOf(const char* format, std::int64_t vertices, const std::string& header, const std::string& records)
{
  return std::string("ply\nformat ") + format + " 1.0\ncomment made by a test\nelement vertex " +
    std::to_string(vertices) + "\n" + header + "end_header\n" + records;
}

template <class T>
void put(std::string& bytes, T value, bool bigEndian)
{
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (bigEndian)
  {
    std::reverse(b, b + sizeof(T));
  }
  bytes.append(b, sizeof(T));
}

/// Reads `bytes` as a PLY in shares: its layout's verdict, and the gathered points.
bool readPly(
  const std::string& name, const std::string& bytes, Points& gathered, std::int64_t& total, bool* wide = nullptr)
{
  auto comm = world();
  const std::string path = sharedFile(*comm, name, bytes);
  std::ifstream in(path, std::ios::binary);
  sltk::PlyVertexLayout layout;
  const bool split = sltk::plyVertexLayout(in, static_cast<std::int64_t>(bytes.size()), layout);
  if (split)
  {
    sltk::CloudShare share;
    EXPECT_TRUE(sltk::readPlyCloudShare(path, layout, *comm, share).isOk());
    gathered = comm->allGatherV(share.Points);
    total = share.Total;
  }
  if (wide)
  {
    *wide = layout.Wide;
  }
  removeShared(*comm, path);
  return split;
}
} // namespace

TEST(CloudFiles, BinaryPlyByVertexRecords)
{
  for (bool big : { false, true })
  {
    // y as int, then x as double, then z as float: the file's values (wide: the CLI keeps them in double).
    std::string records;
    Points expected;
    for (int i = 0; i < 37; ++i)
    {
      const double x = 0.1 * i + 1e-9, z = -0.3 * i;
      put<std::int32_t>(records, i * 7 - 100, big);
      put<double>(records, x, big);
      put<float>(records, static_cast<float>(z), big);
      expected.push_back({ x, double(i * 7 - 100), double(float(z)) });
    }
    Points gathered;
    std::int64_t total = 0;
    bool wide = false;
    ASSERT_TRUE(readPly("points.ply",
      plyOf(big ? "binary_big_endian" : "binary_little_endian", 37,
        "property int y\nproperty double x\nproperty float z\n", records),
      gathered, total, &wide));
    EXPECT_EQ(gathered, expected) << (big ? "big" : "little") << " endian";
    EXPECT_EQ(total, 37);
    EXPECT_TRUE(wide);
  }
  // Float and short coordinates: not wide (the CLI stores them in float, as vtkPLYReader does).
  std::string records;
  put<float>(records, 0.1f, false);
  put<std::int16_t>(records, -3, false);
  put<float>(records, 2.5f, false);
  Points gathered;
  std::int64_t total = 0;
  bool wide = true;
  ASSERT_TRUE(readPly("narrow.ply",
    plyOf("binary_little_endian", 1, "property float x\nproperty short y\nproperty float z\n", records), gathered,
    total, &wide));
  EXPECT_EQ(gathered, Points({ { double(0.1f), -3.0, 2.5 } }));
  EXPECT_FALSE(wide);
}

TEST(CloudFiles, PlyWithMoreThanPointsIsLeftToTheWholeRead)
{
  Points gathered;
  std::int64_t total = 0;
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  EXPECT_FALSE(readPly("normals.ply",
    plyOf("binary_little_endian", 1, xyz + "property float nx\n", std::string(16, '\0')), gathered, total));
  EXPECT_FALSE(readPly("ascii.ply", plyOf("ascii", 1, xyz, "1 2 3\n"), gathered, total));
  EXPECT_FALSE(readPly("faces.ply",
    plyOf("binary_little_endian", 1, xyz + "element face 1\nproperty list uchar int vertex_indices\n",
      std::string(12, '\0') + std::string("\x01\0\0\0\0", 5)),
    gathered, total));
  EXPECT_FALSE(readPly("short.ply", plyOf("binary_little_endian", 2, xyz, std::string(12, '\0')), gathered, total));
  EXPECT_TRUE(readPly("empty-faces.ply",
    plyOf("binary_little_endian", 1, xyz + "element face 0\nproperty list uchar int vertex_indices\n",
      std::string(12, '\0')),
    gathered, total));
  EXPECT_EQ(gathered, Points({ { 0, 0, 0 } }));
}
