// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file OutputPaths.h
/// Checks of the CLI's output files before any work: an output must not be
/// one of the inputs (a scan overwritten by `-o scan.ply`), nor another
/// output, its extension must be the format written (`-o out.xyz` would hold
/// VTK XML), and its folder must exist and be writable, so a long run never
/// ends by failing to write or by destroying its data.

#include <string>
#include <utility>
#include <vector>

namespace sltkcli
{

/// A file the command reads: what it is ("input cloud") and its path.
using NamedPath = std::pair<std::string, std::string>;

/// A file the command writes: the option, the path, and the extensions its
/// format goes by ("vti"; empty: any, the writer chooses by extension).
struct OutputFile
{
  std::string Option;
  std::string Path;
  std::vector<std::string> Extensions;
};

/// "" when every output is fine; otherwise the first problem, naming the
/// options, the path and the fix. Empty paths (options not given) are skipped.
std::string outputPathsProblem(const std::vector<NamedPath>& inputs, const std::vector<OutputFile>& outputs);

} // namespace sltkcli
