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
/// WENO3 (2.69), CWENO and CWENOZ (3.3, Definition 3.1), and the thesis's
/// chapter 5 least-squares Q1 (5.5), which only the reconstruction offers.

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
  CwenoZ = 3,
  LeastSquaresQ1 = 4
};

/// The solvers that offer an interpolator.
enum class InterpolatorSolvers : std::uint8_t
{
  All,               ///< the reconstruction and the HJB solver
  ReconstructionOnly ///< its fit needs a node's whole 3^D neighbourhood in the band (LsqQ1.h)
};

struct InterpolatorInfo
{
  InterpolatorKind Kind;
  const char* Name;        ///< command-line name (lower case)
  const char* Label;       ///< ParaView enumeration text
  const char* Description; ///< one line for --help and the plugin documentation
  InterpolatorSolvers Solvers;
};

// clang-format off
/// One row per kind, in the order of the enum values (the plugin XML is generated from these rows;
/// the HJB filter's enumeration leaves out the ReconstructionOnly ones, which come last).
inline constexpr std::array<InterpolatorInfo, 5> Interpolators = { {
  { InterpolatorKind::Q1, "q1", "Q1", "multilinear (4.28), monotone, first order", InterpolatorSolvers::All },
  { InterpolatorKind::Weno3, "weno3", "WENO3", "third-order WENO, dimension by dimension (2.69)", InterpolatorSolvers::All },
  { InterpolatorKind::Cweno, "cweno", "CWENO", "third-order CWENO, one polynomial per cell (3.3)", InterpolatorSolvers::All },
  { InterpolatorKind::CwenoZ, "cwenoz", "CWENOZ", "CWENO with the Z weights of (3.28)", InterpolatorSolvers::All },
  { InterpolatorKind::LeastSquaresQ1, "lsq-q1", "Least-squares Q1", "least-squares Q1 of the nearest node (5.5), discontinuous between cells", InterpolatorSolvers::ReconstructionOnly },
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

/// Whether the HJB solver offers `kind` (every kind but the reconstruction's own).
inline bool offeredByHjb(InterpolatorKind kind)
{
  return interpolatorInfo(kind).Solvers == InterpolatorSolvers::All;
}

namespace detail
{
constexpr std::size_t hjbInterpolatorCount()
{
  std::size_t n = 0;
  for (const InterpolatorInfo& info : Interpolators)
  {
    n += info.Solvers == InterpolatorSolvers::All ? 1 : 0;
  }
  return n;
}

constexpr std::array<InterpolatorInfo, hjbInterpolatorCount()> hjbInterpolatorRows()
{
  std::array<InterpolatorInfo, hjbInterpolatorCount()> rows{};
  std::size_t k = 0;
  for (const InterpolatorInfo& info : Interpolators)
  {
    if (info.Solvers == InterpolatorSolvers::All)
    {
      rows[k++] = info;
    }
  }
  return rows;
}
} // namespace detail

/// The rows of the kinds the HJB solver offers, in the registry's order (their values are 0..size-1).
inline constexpr auto HjbInterpolators = detail::hjbInterpolatorRows();

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

/// interpolatorOfCode for the HJB solver: a kind only the reconstruction offers is
/// refused too, naming the ones the HJB solver offers.
Status hjbInterpolatorOfCode(int code, InterpolatorKind& kind);

/// The kind named `name` (command-line name or label, any case); false when unknown.
bool parseInterpolator(const std::string& name, InterpolatorKind& kind);

/// "q1, weno3, cweno, cwenoz or lsq-q1": the reconstruction's names for an error
/// message or a usage line.
std::string interpolatorNameList();

/// "q1, weno3, cweno or cwenoz": the HJB solver's.
std::string hjbInterpolatorNameList();

} // namespace sltk
