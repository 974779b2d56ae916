// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/exec/Context.h"

namespace sltk
{

namespace
{
class NullLogger final : public Logger
{
public:
  void log(LogLevel, const std::string&) override {}
};
} // namespace

Interrupter& nullInterrupter()
{
  static Interrupter never;
  return never;
}

Logger& nullLogger()
{
  static NullLogger silent;
  return silent;
}

ThreadPool& Context::serialExecutor()
{
  static ThreadPool serial(1);
  return serial;
}

} // namespace sltk
