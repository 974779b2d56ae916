// SPDX-License-Identifier: BSD-3-Clause
#include "WriteAtomically.h"

#include <cstdio>
#include <fstream>
#include <unistd.h>

namespace sltkcli
{

sltk::Status writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
  // Keep the extension last: VTK writers do not care, but readers of partial names might.
  const std::string temporary = path + ".part" + std::to_string(::getpid());
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
  return writeAtomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary);
    out << text;
    out.close();
    return static_cast<bool>(out);
  });
}

} // namespace sltkcli
