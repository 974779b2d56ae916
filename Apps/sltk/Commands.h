// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Commands.h
/// Sub-commands of the `sltk` command line. Each adds its CLI11 parser to the
/// program's; its run returns the process exit code: 0 success, 1 the job failed,
/// 2 bad usage (options that contradict each other; CLI11's parse errors are
/// printed by main(), also with 2), 3 a reconstruction whose result does not fit
/// its cloud (ReconstructionResult::FitsCloud; the files are written). Failures
/// print their message.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace sltkcli
{

/// A sub-command: its parser, and what runs it once the command line parsed.
struct Command
{
  CLI::App* Parser = nullptr;
  std::function<int()> Run;
};

Command addInfoCommand(CLI::App& sltk);
Command addReconstructCommand(CLI::App& sltk);
Command addHjbCommand(CLI::App& sltk);

/// A grid refused for memory ("... use C_dx >= ...") on a large cloud that was not
/// thinned: appends the hint that merged, overlapping range scans make h_P (4.36)
/// tiny and want --remove-outliers --thin (README). Other messages are returned as they are.
std::string withMergedScanHint(const std::string& message, size_t points, bool thinned);

/// Prints "sltk: error: <message>" to stderr and returns `code`.
int fail(const std::string& message, int code = 1);

} // namespace sltkcli
