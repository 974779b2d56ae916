// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Logger.h
/// Injected logging sink. Core never prints: it logs through this interface,
/// which the filters forward to vtkLogger and the CLI to stderr.

#include <string>

namespace sltk
{

enum class LogLevel
{
  Error = 0,
  Warning,
  Info,
  Debug
};

class Logger
{
public:
  virtual ~Logger() = default;
  virtual void log(LogLevel level, const std::string& message) = 0;
};

/// A logger that drops everything.
Logger& nullLogger();

} // namespace sltk
