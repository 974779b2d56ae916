// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file OrList.h
/// "a, b or c": the choices of an error message or a usage line.

#include <string>
#include <vector>

namespace sltk
{

inline std::string orList(const std::vector<std::string>& items)
{
  std::string list;
  for (size_t k = 0; k < items.size(); ++k)
  {
    list += (k == 0 ? "" : k + 1 == items.size() ? " or " : ", ") + items[k];
  }
  return list;
}

} // namespace sltk
