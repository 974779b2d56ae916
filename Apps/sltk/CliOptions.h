// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CliOptions.h
/// CLI11 options the sub-commands share, with sltk's checks and messages: numbers
/// (the whole text, finite, whole for counts), number lists, names from a list, the
/// interpolator from the registry (InterpolatorKind.h), --threads and the options
/// of a reconstruction plan (`sltk info` and `sltk reconstruct`). CLI11 reports a
/// failed check as "--option: message"; main() prints it and exits 2.

#include "sltk/core/OrList.h"
#include "sltk/recon/ReconstructionOptions.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace sltkcli
{

/// A number option bound to `value`: "--cdx: expects a number, got '0.02abc'" unless
/// the whole text is a finite number (a whole one for an int).
CLI::Option* addNumber(CLI::App* app, const std::string& name, double& value, const std::string& description);
CLI::Option* addNumber(CLI::App* app, const std::string& name, int& value, const std::string& description);

/// A check of an addNumber option: "must be in [low, high], got x" (`lowOpen`: (low, high]).
CLI::Validator within(double low, double high = std::numeric_limits<double>::infinity(), bool lowOpen = false);
/// The range of a property in Core's table (sltk/recon/OptionRanges.h), as the filters check it.
CLI::Validator withinRange(const char* property);

/// "v1,v2,...": minCount to maxCount finite numbers, stored in `values` (kept when the option is absent).
CLI::Option* addNumberList(CLI::App* app, const std::string& name, std::vector<double>& values, size_t minCount,
  size_t maxCount, const std::string& description);

/// A name from `names`: calls chosen(its index); "unknown <what> 'x': use a, b or c" otherwise.
CLI::Option* addChoice(CLI::App* app, const std::string& name, const std::string& what,
  const std::vector<std::string>& names, const std::function<void(size_t)>& chosen, const std::string& description);

/// `sltk hjb --interpolator NAME`: a name (or label) of the kinds the HJB solver offers
/// (offeredByHjb), their list and descriptions in the help.
CLI::Option* addInterpolatorOption(CLI::App* app, sltk::InterpolatorKind& kind, const std::string& defaultName);

/// `sltk reconstruct --interpolator NAME`: every kind of the registry, or "auto"
/// (empty: ReconstructionOptions::Interpolator chosen from the cloud's noise).
CLI::Option* addReconstructionInterpolatorOption(CLI::App* app, std::optional<sltk::InterpolatorKind>& kind);

/// --threads T (>= 0; default 0: all).
CLI::Option* addThreadsOption(CLI::App* app, int& threads);

/// A sub-command of one point cloud, `sltk <name> CLOUD [options]`, the path bound to `cloud`.
CLI::App* addCloudCommand(CLI::App& sltk, const std::string& name, const std::string& description, std::string& cloud);

/// The options of a reconstruction plan, bound to `options`: --runs --cdx --kp --initial
/// --remove-outliers --outlier-sigma --thin (ranges are the caller's).
void addPlanOptions(CLI::App* app, sltk::ReconstructionOptions& options);

} // namespace sltkcli
