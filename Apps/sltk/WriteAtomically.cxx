// SPDX-License-Identifier: BSD-3-Clause
#include "WriteAtomically.h"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>
#include <vector>

namespace sltkcli
{

namespace
{
/// The temporary files (then folders) being written, for the signal handler
/// (fixed buffers: only async-signal-safe calls may touch them there).
constexpr int MaxPending = 4;
char PendingFiles[MaxPending][4096] = {};
char PendingFolders[MaxPending][4096] = {};

extern "C" void removePendingAndDie(int signal)
{
  for (int k = 0; k < MaxPending; ++k)
  {
    if (PendingFiles[k][0])
    {
      ::unlink(PendingFiles[k]);
    }
  }
  for (int k = 0; k < MaxPending; ++k)
  {
    if (PendingFolders[k][0])
    {
      ::rmdir(PendingFolders[k]);
    }
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void store(char (&slots)[MaxPending][4096], const std::vector<std::string>& paths)
{
  for (int k = 0; k < MaxPending; ++k)
  {
    const std::string path = k < static_cast<int>(paths.size()) ? paths[static_cast<size_t>(k)] : std::string();
    slots[k][0] = '\0';
    if (path.size() < sizeof(slots[k]))
    {
      std::memcpy(slots[k], path.c_str(), path.size() + 1);
    }
  }
}

void setPending(const std::string& temporary)
{
  setPendingPaths(temporary.empty() ? std::vector<std::string>{} : std::vector<std::string>{ temporary }, {});
}
} // namespace

void setPendingPaths(const std::vector<std::string>& files, const std::vector<std::string>& folders)
{
  static const bool installed = []
  {
    std::signal(SIGINT, removePendingAndDie);
    std::signal(SIGTERM, removePendingAndDie);
    return true;
  }();
  (void)installed;
  store(PendingFiles, {});
  store(PendingFolders, folders);
  store(PendingFiles, files);
}

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
