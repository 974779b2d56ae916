// SPDX-License-Identifier: BSD-3-Clause
#include "FileNames.h"

#include "sltk/core/LowerCase.h"

namespace sltkcli
{

std::string extensionOf(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  return sltk::lowerCase(path.substr(dot + 1));
}

} // namespace sltkcli
