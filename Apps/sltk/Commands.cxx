// SPDX-License-Identifier: BSD-3-Clause
#include "Commands.h"

#include <iostream>
#include <string>

namespace sltkcli
{

std::string withMergedScanHint(const std::string& message, size_t points, bool thinned)
{
  constexpr size_t manyPoints = 100000; // a single laser scan of an object rarely has more
  if (thinned || points < manyPoints || message.find("use C_dx >=") == std::string::npos)
  {
    return message;
  }
  return message +
    ". If the cloud merges overlapping range scans, their overlaps make h_P tiny: try "
    "--remove-outliers --thin 2.5 (README, merged scans), then sltk info with the same options";
}

int fail(const std::string& message, int code)
{
  std::cerr << "sltk: error: " << message << "\n";
  return code;
}

} // namespace sltkcli
