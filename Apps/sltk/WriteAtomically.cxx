// SPDX-License-Identifier: BSD-3-Clause
#include "WriteAtomically.h"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace sltkcli
{

namespace
{
/// The temporary file being written, for the signal handler (a fixed buffer:
/// only async-signal-safe calls may touch it there).
char PendingTemporary[4096] = { 0 };

extern "C" void removePendingAndDie(int signal)
{
  if (PendingTemporary[0])
  {
    ::unlink(PendingTemporary);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// Registers `temporary` as the file to remove if SIGINT or SIGTERM arrives
/// while it is written; an empty name clears it.
void setPending(const std::string& temporary)
{
  static const bool installed = []
  {
    std::signal(SIGINT, removePendingAndDie);
    std::signal(SIGTERM, removePendingAndDie);
    return true;
  }();
  (void)installed;
  PendingTemporary[0] = '\0';
  if (temporary.size() < sizeof(PendingTemporary))
  {
    std::memcpy(PendingTemporary, temporary.c_str(), temporary.size() + 1);
  }
}
} // namespace

sltk::Status writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
  // "name.part<pid>.ext": some writers choose their format by the extension.
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = hasExtension ? path.substr(0, dot) : path;
  const std::string extension = hasExtension ? path.substr(dot) : "";
  const std::string temporary = stem + ".part" + std::to_string(::getpid()) + extension;
  setPending(temporary); // an interrupted write leaves no .part file
  const bool written = write(temporary);
  if (!written)
  {
    std::remove(temporary.c_str());
    setPending(std::string());
    return sltk::Status::ioError("could not write " + path + ": check that the directory exists and is writable");
  }
  const bool moved = std::rename(temporary.c_str(), path.c_str()) == 0;
  if (!moved)
  {
    std::remove(temporary.c_str());
  }
  setPending(std::string());
  return moved ? sltk::Status::ok() : sltk::Status::ioError("could not move the finished file to " + path);
}

sltk::Status writeTextFile(const std::string& path, const std::string& text)
{
  return writeAtomically(path,
    [&](const std::string& temporary)
    {
      std::ofstream out(temporary);
      out << text;
      out.close();
      return static_cast<bool>(out);
    });
}

sltk::Status writeJsonFile(const std::string& path, const nlohmann::ordered_json& value)
{
  return writeTextFile(path, value.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

} // namespace sltkcli
