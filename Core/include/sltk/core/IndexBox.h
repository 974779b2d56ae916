// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file IndexBox.h
/// Visiting every integer point of a box of indices.

#include "sltk/core/Index.h"

#include <array>

namespace sltk
{

/// Calls f(i) for every i with lo <= i <= hi componentwise, the first axis
/// fastest; nothing when a range is empty.
template <int D, class F>
void forEachIndexInBox(const std::array<Index, D>& lo, const std::array<Index, D>& hi, F&& f)
{
  for (int a = 0; a < D; ++a)
  {
    if (hi[a] < lo[a])
    {
      return;
    }
  }
  std::array<Index, D> i = lo;
  while (true)
  {
    f(static_cast<const std::array<Index, D>&>(i));
    int a = 0;
    for (; a < D; ++a)
    {
      if (++i[a] <= hi[a])
      {
        break;
      }
      i[a] = lo[a];
    }
    if (a == D)
    {
      return;
    }
  }
}

} // namespace sltk
