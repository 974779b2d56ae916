// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ResizeForOverwrite.h
/// Resizing a buffer that the caller then overwrites entry by entry, and that
/// is kept from call to call so that its pages are faulted in once
/// (Documentation/Profile.md, "Page faults of the per-iteration arrays").

#include <cstddef>
#include <vector>

namespace sltk
{

/// `v` with n entries, each to be overwritten: within its capacity the pages
/// it holds are reused; beyond it, the old entries are dropped rather than
/// copied, and the new capacity is n, not twice the old size.
template <class T>
void resizeForOverwrite(std::vector<T>& v, std::size_t n)
{
  if (n > v.capacity())
  {
    v.clear();
  }
  v.resize(n);
}

} // namespace sltk
