// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/interp/InterpolatorKind.h"

#include <algorithm>
#include <cctype>

namespace sltk
{

namespace
{
std::string lowerCase(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}
} // namespace

bool parseInterpolator(const std::string& name, InterpolatorKind& kind)
{
  const std::string wanted = lowerCase(name);
  for (const InterpolatorInfo& info : Interpolators)
  {
    if (wanted == info.Name || wanted == lowerCase(info.Label))
    {
      kind = info.Kind;
      return true;
    }
  }
  return false;
}

std::string interpolatorNameList()
{
  std::string list;
  for (int k = 0; k < interpolatorCount(); ++k)
  {
    list += k == 0 ? "" : (k + 1 == interpolatorCount() ? " or " : ", ");
    list += Interpolators[static_cast<std::size_t>(k)].Name;
  }
  return list;
}

} // namespace sltk
