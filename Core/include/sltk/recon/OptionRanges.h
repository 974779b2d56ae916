// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file OptionRanges.h
/// The ranges of the options a user sets, one row each: the one source of
/// Core's validation, the filters' property checks, the CLI's checks and the
/// ParaView plugin XML's range domains (Plugin/CMakeLists.txt reads the rows of
/// OptionRanges below into the XML at configure time: keep one row a line, in
/// this form). A value outside its range is refused with its name and range,
/// never clamped. An option whose 0 means "automatic" takes 0 or a value in
/// [Min, Max]; its XML domain starts at 0 (a range domain cannot leave a gap)
/// and the filter refuses the values between 0 and Min with this message.

#include "sltk/core/Status.h"

#include <sstream>
#include <string>

namespace sltk
{

struct OptionRange
{
  const char* Property; ///< the filters' property (ParaView, pvpython, C++); the CLI's flags name theirs
  double Min;
  double Max;
  bool ZeroIsAutomatic; ///< 0 asks the automatic choice
};

// The reconstruction's (vtkSLLevelSetReconstruct, vtkOctreeSDF, sltk reconstruct), then the HJB
// solver's (vtkCWENOHJBSolver, sltk hjb); NumberOfThreads is both's.
// clang-format off
inline constexpr OptionRange OptionRanges[] = {
  { "NumberOfRuns", 1, 6, false },
  { "CellSizeFactor", 0.05, 100, true },
  { "MaximumLevel", 1, 30, true },
  { "OutsideThresholdFactor", 0.1, 100, true },
  { "MaximumNumberOfIterations", 1, 100000, false },
  { "Tolerance", 0, 1, false },
  { "Padding", 4, 1000, false },
  { "FinalEta", 0, 100, false },
  { "OutlierDeviations", 0.5, 100, false },
  { "ThinningFactor", 0, 100, false },
  { "MemoryBudget", 16, 100000000, true },
  { "NumberOfThreads", 0, 1024, false },
  { "NumberOfNodes", 5, 100000, false },
  { "CourantNumber", 0, 100, false },
  { "Dimensions", 1, 100000, false },
  { "ControlDimension", 1, 3, false },
  { "TabulationPoints", 1, 1000, false },
  { "WarmStartPoints", 0, 15, false },
  { "MinimizerTolerance", 0, 1, false },
};
// clang-format on

constexpr bool sameOptionName(const char* a, const char* b)
{
  while (*a != '\0' && *a == *b)
  {
    ++a;
    ++b;
  }
  return *a == *b;
}

inline constexpr int OptionRangeCount = static_cast<int>(sizeof(OptionRanges) / sizeof(OptionRanges[0]));

/// The row number of `property`; -1 when it has none.
constexpr int optionRangeIndex(const char* property)
{
  for (int i = 0; i < OptionRangeCount; ++i)
  {
    if (sameOptionName(OptionRanges[i].Property, property))
    {
      return i;
    }
  }
  return -1;
}

/// The row of `property`; nullptr when it has none.
inline const OptionRange* findOptionRange(const char* property)
{
  const int i = optionRangeIndex(property);
  return i >= 0 ? &OptionRanges[i] : nullptr;
}

/// The row of `property`, evaluated at compile time where it is used as a
/// constant (a name without a row does not compile there).
constexpr const OptionRange& optionRange(const char* property)
{
  return optionRangeIndex(property) >= 0 ? OptionRanges[optionRangeIndex(property)]
                                         : throw "OptionRanges.h: no row for this property";
}

inline bool inOptionRange(const OptionRange& r, double value)
{
  return (value >= r.Min && value <= r.Max) || (r.ZeroIsAutomatic && value == 0.0);
}

/// ok, or the refusal naming `name` (the property or the flag), its value and its range.
inline Status checkOptionRange(const OptionRange& r, double value, const std::string& name)
{
  if (inOptionRange(r, value))
  {
    return Status::ok();
  }
  std::ostringstream m;
  m << name << " = " << value << " is outside its range [" << r.Min << ", " << r.Max << "]: set a value in it"
    << (r.ZeroIsAutomatic ? ", or 0 for automatic" : "");
  return Status::invalidArgument(m.str());
}

} // namespace sltk
