// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/interp/InterpolatorKind.h"

#include "sltk/core/LowerCase.h"
#include "sltk/core/OrList.h"

#include <vector>

namespace sltk
{

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
  std::vector<std::string> names;
  for (const InterpolatorInfo& info : Interpolators)
  {
    names.emplace_back(info.Name);
  }
  return orList(names);
}

} // namespace sltk
