// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the CLI's cloud reading path (ReadPointCloud.h) on any
// bytes, as a text cloud (.xyz) or as a PLY file (checkPlyFile, then
// vtkPLYReader when the check passes): SLTK_FUZZ_READER=xyz or ply picks one
// reader for every input; unset, the first byte of each input picks it. The input is written to a file in
// /dev/shm because the readers take paths. A crash, an abort inside VTK, a
// sanitizer report or a hang is a bug; an error Status is the expected answer.
#include "ReadPointCloud.h"

#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkPointSet.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
const char* forcedReader = nullptr; ///< ".xyz", ".ply" or null (the first byte decides)

std::string scratchPath(const char* extension)
{
  return "/dev/shm/sltk-fuzz-" + std::to_string(::getpid()) + extension;
}

void readAs(const char* extension, const std::uint8_t* data, std::size_t size)
{
  const std::string path = scratchPath(extension);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  vtkSmartPointer<vtkPointSet> cloud;
  const sltk::Status status = sltkcli::readPointCloud(path, cloud);
  if (status.isOk() && (!cloud || cloud->GetNumberOfPoints() < 0))
  {
    __builtin_trap(); // a success must come with a point set
  }
  std::remove(path.c_str());
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkObject::GlobalWarningDisplayOff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const char* reader = std::getenv("SLTK_FUZZ_READER");
  if (reader && std::strcmp(reader, "xyz") == 0)
  {
    forcedReader = ".xyz";
  }
  else if (reader && std::strcmp(reader, "ply") == 0)
  {
    forcedReader = ".ply";
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (forcedReader)
  {
    readAs(forcedReader, data, size);
    return 0;
  }
  // The first byte picks the reader, so that one corpus serves both.
  if (size == 0)
  {
    return 0;
  }
  readAs(data[0] & 1 ? ".ply" : ".xyz", data + 1, size - 1);
  return 0;
}
