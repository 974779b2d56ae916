// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LowerCase.h
/// ASCII lower case: names and file extensions compared in any case.

#include <algorithm>
#include <cctype>
#include <string>

namespace sltk
{

inline std::string lowerCase(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

} // namespace sltk
