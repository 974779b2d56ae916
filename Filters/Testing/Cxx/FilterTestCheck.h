// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FilterTestCheck.h
/// The filter tests' check: a failed check is printed and counted, the test
/// goes on, and main() returns failure when any check failed.

#include <iostream>
#include <string>

namespace sltktest
{

inline int& failures()
{
  static int count = 0;
  return count;
}

inline void check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++failures();
  }
}

} // namespace sltktest
