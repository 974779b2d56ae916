// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ThesisNames.h
/// The one mapping from the interpolator registry (sltk/interp/InterpolatorKind.h)
/// to the thesis's names for the interpolators: the column keys of
/// thesis_tables.json ("Q1", "WENO" for weno3, "CWENO", "CWENOZ"). The
/// benchmarks loop over the registry, print its labels and look the thesis's
/// columns up with thesisKey(); on their command lines they take the registry's
/// names and the thesis's keys alike ("weno" for weno3).

#include "sltk/interp/InterpolatorKind.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace sltkbench
{

/// The key of `kind`'s columns in thesis_tables.json: its registry label, but
/// "WENO" for WENO3. A table without that key (chapter 3 has no Q1, chapter 4
/// no CWENO, the thesis no interpolator added since) has no thesis value for `kind`.
inline const char* thesisKey(sltk::InterpolatorKind kind)
{
  return kind == sltk::InterpolatorKind::Weno3 ? "WENO" : sltk::interpolatorInfo(kind).Label;
}

/// The kind named `name` on a benchmark's command line: a registry name or
/// label, or a thesis key ("weno"), in any case. False for an unknown name.
inline bool parseBenchInterpolator(const std::string& name, sltk::InterpolatorKind& kind)
{
  if (sltk::parseInterpolator(name, kind))
  {
    return true;
  }
  auto upper = [](std::string s)
  {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
  };
  for (const sltk::InterpolatorInfo& info : sltk::Interpolators)
  {
    if (upper(name) == thesisKey(info.Kind))
    {
      kind = info.Kind;
      return true;
    }
  }
  return false;
}

} // namespace sltkbench
