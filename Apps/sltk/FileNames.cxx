// SPDX-License-Identifier: BSD-3-Clause
#include "FileNames.h"

#include <algorithm>
#include <cctype>

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
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

} // namespace sltkcli
