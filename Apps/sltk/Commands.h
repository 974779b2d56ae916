// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Commands.h
/// Sub-commands of the `sltk` command line. Each returns the process exit
/// code: 0 success, 1 the job failed (message printed), 2 bad usage.

#include "sltk/recon/ReconstructionOptions.h"

#include <string>
#include <vector>

namespace sltkcli
{

using Args = std::vector<std::string>;

int commandInfo(const Args& args);
int commandHjb(const Args& args);
int commandReconstruct(const Args& args);

/// A grid refused for memory ("... use C_dx >= ...") on a large cloud that was not
/// thinned: appends the hint that merged, overlapping range scans make h_P (4.36)
/// tiny and want --remove-outliers --thin (README). Other messages are returned as they are.
std::string withMergedScanHint(const std::string& message, size_t points, bool thinned);

/// The InitialGuess named `name` (outside, sphere, ellipsoid); false when unknown.
bool parseInitialGuess(const std::string& name, sltk::InitialGuess& guess);

/// Prints "sltk: error: <message>" to stderr and returns `code`.
int fail(const std::string& message, int code = 1);

/// Simple option scanner: `--name value` pairs and flags, positional arguments.
class Options
{
public:
  Options(const Args& args, const std::vector<std::string>& valued, const std::vector<std::string>& flags);
  bool ok() const { return this->Error.empty(); }
  const std::string& error() const { return this->Error; }
  bool has(const std::string& name) const;
  std::string value(const std::string& name, const std::string& fallback = "") const;
  /// Parses a number option; sets error() on malformed text.
  double number(const std::string& name, double fallback);
  /// Parses "v1,v2,..." with minCount to maxCount numbers; sets error() otherwise.
  std::vector<double> numbers(
    const std::string& name, size_t minCount, size_t maxCount, const std::vector<double>& fallback);
  const std::vector<std::string>& positional() const { return this->Positional; }

private:
  std::vector<std::pair<std::string, std::string>> Values;
  std::vector<std::string> Positional;
  std::string Error;
};

} // namespace sltkcli
