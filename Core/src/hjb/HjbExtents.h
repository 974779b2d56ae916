// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbExtents.h
/// Boxes of grid nodes (HjbExtent, VTK's extent convention) and copies of node
/// arrays between them: the crop of HjbSolver::resultBlock() and the packing
/// of a distributed solver's blocks (DistributedHjbSolver.h).

#include "sltk/hjb/HjbResult.h"

#include <algorithm>
#include <cstddef>

namespace sltk
{

/// Nodes in `e` (0 when empty).
inline Index extentNodes(const HjbExtent& e)
{
  Index n = 1;
  for (int a = 0; a < 3; ++a)
  {
    n *= std::max<Index>(0, e[2 * a + 1] - e[2 * a] + 1);
  }
  return n;
}

/// The nodes in both boxes.
inline HjbExtent intersectExtents(const HjbExtent& a, const HjbExtent& b)
{
  HjbExtent c;
  for (int k = 0; k < 3; ++k)
  {
    c[2 * k] = std::max(a[2 * k], b[2 * k]);
    c[2 * k + 1] = std::min(a[2 * k + 1], b[2 * k + 1]);
  }
  return c;
}

/// Copies the nodes of `box` from `from` (the nodes of `fromExtent`, x
/// fastest) to `to` (the nodes of `toExtent`); `box` lies in both.
inline void copyExtent(
  const double* from, const HjbExtent& fromExtent, double* to, const HjbExtent& toExtent, const HjbExtent& box)
{
  if (extentNodes(box) == 0)
  {
    return;
  }
  const Index fromNx = fromExtent[1] - fromExtent[0] + 1, fromNy = fromExtent[3] - fromExtent[2] + 1;
  const Index toNx = toExtent[1] - toExtent[0] + 1, toNy = toExtent[3] - toExtent[2] + 1;
  const auto row = static_cast<std::ptrdiff_t>(box[1] - box[0] + 1);
  for (Index k = box[4]; k <= box[5]; ++k)
  {
    for (Index j = box[2]; j <= box[3]; ++j)
    {
      const Index f = (box[0] - fromExtent[0]) + fromNx * ((j - fromExtent[2]) + fromNy * (k - fromExtent[4]));
      const Index t = (box[0] - toExtent[0]) + toNx * ((j - toExtent[2]) + toNy * (k - toExtent[4]));
      std::copy(from + f, from + f + row, to + t);
    }
  }
}

} // namespace sltk
