// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/cloud/CloudPieces.h"

#include <algorithm>
#include <limits>

namespace sltk
{

namespace
{
/// size, then per axis: sum, sum of squares, min, max (an empty cloud: +-inf).
template <int D>
std::vector<double> fingerprint(const PointCloud<D>& cloud)
{
  std::vector<double> print(1 + 4 * D, 0.0);
  print[0] = static_cast<double>(cloud.size());
  for (int a = 0; a < D; ++a)
  {
    print[1 + 4 * a + 2] = std::numeric_limits<double>::infinity();
    print[1 + 4 * a + 3] = -std::numeric_limits<double>::infinity();
  }
  for (const auto& p : cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      double* axis = &print[static_cast<size_t>(1 + 4 * a)];
      axis[0] += p[a];
      axis[1] += p[a] * p[a];
      axis[2] = std::min(axis[2], p[a]);
      axis[3] = std::max(axis[3], p[a]);
    }
  }
  return print;
}
} // namespace

template <int D>
bool joinCloudPieces(PointCloud<D>& cloud, const Communicator& comm)
{
  if (comm.size() == 1)
  {
    return false;
  }
  // NaN coordinates make every comparison false: such clouds count as different and are
  // joined, so that the validation after sees every rank's NaN.
  const std::vector<double> print = fingerprint(cloud);
  std::vector<double> low = print, high = print;
  comm.allReduce(low.data(), low.size(), ReduceOp::Min);
  comm.allReduce(high.data(), high.size(), ReduceOp::Max);
  bool same = true;
  for (size_t i = 0; i < print.size(); ++i)
  {
    same = same && low[i] == high[i];
  }
  if (same)
  {
    return false;
  }
  cloud.Points = comm.allGatherV(cloud.Points);
  return true;
}

template bool joinCloudPieces(PointCloud<2>&, const Communicator&);
template bool joinCloudPieces(PointCloud<3>&, const Communicator&);

} // namespace sltk
