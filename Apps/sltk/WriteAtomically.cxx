// SPDX-License-Identifier: BSD-3-Clause
#include "WriteAtomically.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace sltkcli
{

sltk::Status writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
  // "name.part<pid>.ext": some writers choose their format by the extension.
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = hasExtension ? path.substr(0, dot) : path;
  const std::string extension = hasExtension ? path.substr(dot) : "";
  const std::string temporary = stem + ".part" + std::to_string(::getpid()) + extension;
  if (!write(temporary))
  {
    std::remove(temporary.c_str());
    return sltk::Status::ioError("could not write " + path + ": check that the directory exists and is writable");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    return sltk::Status::ioError("could not move the finished file to " + path);
  }
  return sltk::Status::ok();
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
