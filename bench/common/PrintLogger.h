// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file PrintLogger.h
/// A benchmark's --log: the library's messages up to a level, on stdout
/// between the tables.

#include "sltk/exec/Logger.h"

#include <cstdio>
#include <string>

namespace sltkbench
{

class PrintLogger : public sltk::Logger
{
public:
  explicit PrintLogger(sltk::LogLevel most = sltk::LogLevel::Info)
    : Most(most)
  {
  }

  void log(sltk::LogLevel level, const std::string& message) override
  {
    if (level <= this->Most)
    {
      std::printf("  [sltk] %s\n", message.c_str());
      std::fflush(stdout);
    }
  }

private:
  sltk::LogLevel Most;
};

} // namespace sltkbench
