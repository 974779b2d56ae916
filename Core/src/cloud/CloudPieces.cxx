// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudPieces.h"

#include <cmath>
#include <cstring>
#include <unordered_set>

namespace sltk
{

namespace
{
/// splitmix64's finaliser: a well-mixed 64-bit hash of a 64-bit word.
std::uint64_t mix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// A hash of a point's coordinate bits (+0 and -0 alike).
template <int D>
std::uint64_t pointHash(const std::array<double, D>& p)
{
  std::uint64_t h = 0;
  for (int a = 0; a < D; ++a)
  {
    const double v = p[a] == 0.0 ? 0.0 : p[a];
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    h = mix(h ^ mix(bits + static_cast<std::uint64_t>(a)));
  }
  return h;
}

/// How the ranks' clouds compare: whether their counts or hashes differ, and
/// whether every coordinate is finite (joinCloudPieces' rule). Collective.
struct PieceComparison
{
  bool Differ = false;
  bool Finite = true;
  std::int64_t Fewest = 0; ///< the fewest points a rank holds
};

template <int D>
PieceComparison comparePieces(const PointCloud<D>& cloud, const Communicator& comm)
{
  std::uint64_t sum = 0;
  std::int64_t finite = 1;
  for (const auto& p : cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      finite = finite && std::isfinite(p[a]) ? 1 : 0;
    }
    sum += pointHash<D>(p); // mod 2^64: the order of the points does not matter
  }
  std::int64_t low[3] = { cloud.size(), static_cast<std::int64_t>(sum >> 1), static_cast<std::int64_t>(sum & 1) };
  std::int64_t high[3] = { low[0], low[1], low[2] };
  comm.allReduce(low, 3, ReduceOp::Min);
  comm.allReduce(high, 3, ReduceOp::Max);
  PieceComparison c;
  c.Finite = comm.allReduce(finite, ReduceOp::Min) != 0;
  c.Differ = low[0] != high[0] || low[1] != high[1] || low[2] != high[2];
  c.Fewest = low[0];
  return c;
}

/// Whether the ranks hold different clouds (joinCloudPieces' rule). Collective.
template <int D>
bool cloudsDiffer(const PointCloud<D>& cloud, const Communicator& comm)
{
  if (comm.size() == 1)
  {
    return false;
  }
  const PieceComparison c = comparePieces(cloud, comm);
  return c.Finite && c.Differ;
}

/// Every rank's points in rank order, exact duplicates of an earlier point dropped. Collective.
template <int D>
void unionOfPieces(PointCloud<D>& cloud, const Communicator& comm)
{
  std::vector<std::array<double, D>> all = comm.allGatherV(cloud.Points);
  struct Hash
  {
    std::size_t operator()(const std::array<double, D>& p) const { return static_cast<std::size_t>(pointHash<D>(p)); }
  };
  std::unordered_set<std::array<double, D>, Hash> seen;
  seen.reserve(all.size());
  cloud.Points.clear();
  for (const auto& p : all)
  {
    if (seen.insert(p).second)
    {
      cloud.Points.push_back(p);
    }
  }
}
} // namespace

template <int D>
bool joinCloudPieces(PointCloud<D>& cloud, const Communicator& comm)
{
  if (!cloudsDiffer(cloud, comm))
  {
    return false;
  }
  unionOfPieces(cloud, comm);
  return true;
}

template <int D>
bool sameCloudOnEveryRank(const PointCloud<D>& cloud, const Communicator& comm)
{
  if (comm.size() == 1)
  {
    return false;
  }
  const PieceComparison c = comparePieces(cloud, comm);
  return c.Finite && !c.Differ && c.Fewest > 0;
}

template bool sameCloudOnEveryRank(const PointCloud<2>&, const Communicator&);
template bool sameCloudOnEveryRank(const PointCloud<3>&, const Communicator&);
template bool joinCloudPieces(PointCloud<2>&, const Communicator&);
template bool joinCloudPieces(PointCloud<3>&, const Communicator&);

} // namespace sltk
