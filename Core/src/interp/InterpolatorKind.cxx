// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/interp/InterpolatorKind.h"

#include "sltk/core/LowerCase.h"
#include "sltk/core/OrList.h"

#include <vector>

namespace sltk
{

Status interpolatorOfCode(int code, InterpolatorKind& kind)
{
  if (interpolatorFromCode(code, kind))
  {
    return Status::ok();
  }
  std::vector<std::string> valid;
  for (const InterpolatorInfo& info : Interpolators)
  {
    valid.push_back(std::to_string(static_cast<int>(info.Kind)) + " (" + info.Label + ")");
  }
  return Status::invalidArgument(
    "Interpolator " + std::to_string(code) + " is not an interpolator: use " + orList(valid));
}

Status hjbInterpolatorOfCode(int code, InterpolatorKind& kind)
{
  SLTK_RETURN_IF_ERROR(interpolatorOfCode(code, kind));
  if (offeredByHjb(kind))
  {
    return Status::ok();
  }
  std::vector<std::string> valid;
  for (const InterpolatorInfo& info : Interpolators)
  {
    if (offeredByHjb(info.Kind))
    {
      valid.push_back(std::to_string(static_cast<int>(info.Kind)) + " (" + info.Label + ", " + info.Name + ")");
    }
  }
  return Status::invalidArgument(std::string("Interpolator ") + std::to_string(code) + " (" +
    interpolatorInfo(kind).Name + ") is the reconstruction's only: the HJB solver offers " + orList(valid));
}

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

namespace
{
std::string nameList(bool hjbOnly)
{
  std::vector<std::string> names;
  for (const InterpolatorInfo& info : Interpolators)
  {
    if (!hjbOnly || offeredByHjb(info.Kind))
    {
      names.emplace_back(info.Name);
    }
  }
  return orList(names);
}
} // namespace

std::string interpolatorNameList()
{
  return nameList(false);
}

std::string hjbInterpolatorNameList()
{
  return nameList(true);
}

} // namespace sltk
