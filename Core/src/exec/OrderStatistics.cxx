// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/OrderStatistics.h"

#include <algorithm>
#include <cstring>

namespace sltk
{

namespace
{
constexpr std::uint64_t SignBit = std::uint64_t(1) << 63;

/// An unsigned key whose order is the numeric order of finite doubles.
std::uint64_t orderKey(double x)
{
  std::uint64_t u = 0;
  std::memcpy(&u, &x, sizeof(u));
  return (u & SignBit) ? ~u : (u | SignBit);
}

double fromOrderKey(std::uint64_t key)
{
  const std::uint64_t u = (key & SignBit) ? (key & ~SignBit) : ~key;
  double x = 0.0;
  std::memcpy(&x, &u, sizeof(x));
  return x;
}
} // namespace

double kthSmallestOverRanks(const std::vector<double>& local, std::int64_t k, const Communicator& comm)
{
  if (comm.size() == 1) // the same value by a selection (-0 and +0 aside), without 64 passes
  {
    std::vector<double> values = local;
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[static_cast<size_t>(k)];
  }
  std::vector<std::uint64_t> keys(local.size());
  for (size_t j = 0; j < local.size(); ++j)
  {
    keys[j] = orderKey(local[j]);
  }
  // The smallest key with more than k values at or below it.
  std::uint64_t low = 0, high = ~std::uint64_t(0);
  while (low < high)
  {
    const std::uint64_t middle = low + (high - low) / 2;
    std::int64_t atOrBelow = 0;
    for (const std::uint64_t key : keys)
    {
      atOrBelow += key <= middle ? 1 : 0;
    }
    if (comm.allReduce(atOrBelow, ReduceOp::Sum) > k)
    {
      high = middle;
    }
    else
    {
      low = middle + 1;
    }
  }
  return fromOrderKey(low);
}

} // namespace sltk
