// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file InterpolatorKind.h
/// The registry of interpolators (Documentation/Architecture.md, "Adding an
/// interpolator"): the run-time choice, its names and its description, in one
/// table that reconstruction, HJB, the filters, the plugin XML (generated from
/// this table at configure time), the CLI and the benchmarks all read. The
/// compile-time dispatch from a kind to its class is in Interpolators.h.
///
/// Spatial reconstructions at the feet of the characteristics: Q1 (4.28),
/// WENO3 (2.69), CWENO and CWENOZ (3.3, Definition 3.1).

#include "sltk/core/Status.h"

#include <array>
#include <cstdint>
#include <string>

namespace sltk
{

enum class InterpolatorKind : std::uint8_t
{
  Q1 = 0,
  Weno3 = 1,
  Cweno = 2,
  CwenoZ = 3
};

struct InterpolatorInfo
{
  InterpolatorKind Kind;
  const char* Name;        ///< command-line name (lower case)
  const char* Label;       ///< ParaView enumeration text
  const char* Description; ///< one line for --help and the plugin documentation
};

// clang-format off
/// One row per kind, in the order of the enum values (the plugin XML is generated from these rows).
inline constexpr std::array<InterpolatorInfo, 4> Interpolators = { {
  { InterpolatorKind::Q1, "q1", "Q1", "multilinear (4.28), monotone, first order" },
  { InterpolatorKind::Weno3, "weno3", "WENO3", "third-order WENO, dimension by dimension (2.69)" },
  { InterpolatorKind::Cweno, "cweno", "CWENO", "third-order CWENO, one polynomial per cell (3.3)" },
  { InterpolatorKind::CwenoZ, "cwenoz", "CWENOZ", "CWENO with the Z weights of (3.28)" },
} };
// clang-format on

constexpr int interpolatorCount()
{
  return static_cast<int>(Interpolators.size());
}

/// The row of a kind (the table is ordered by value).
inline const InterpolatorInfo& interpolatorInfo(InterpolatorKind kind)
{
  return Interpolators[static_cast<std::size_t>(kind)];
}

/// The kind of a value read from a file, a property or a command line; false when out of range.
inline bool interpolatorFromCode(int code, InterpolatorKind& kind)
{
  if (code < 0 || code >= interpolatorCount())
  {
    return false;
  }
  kind = Interpolators[static_cast<std::size_t>(code)].Kind;
  return true;
}

/// The kind of a filter's Interpolator property (or an options' InterpolatorKind
/// as a number); refused with the valid codes and their labels when out of range.
Status interpolatorOfCode(int code, InterpolatorKind& kind);

/// The kind named `name` (command-line name or label, any case); false when unknown.
bool parseInterpolator(const std::string& name, InterpolatorKind& kind);

/// "q1, weno3, cweno or cwenoz": the names for an error message or a usage line.
std::string interpolatorNameList();

} // namespace sltk
