// SPDX-License-Identifier: BSD-3-Clause
#include "OutputPaths.h"

#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace sltkcli
{

namespace
{
namespace fs = std::filesystem;

/// The same file: the same inode when both exist, else the same normalised path.
bool sameFile(const std::string& a, const std::string& b)
{
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec))
  {
    const bool same = fs::equivalent(a, b, ec);
    return !ec && same;
  }
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

std::string folderProblem(const NamedPath& output)
{
  std::error_code ec;
  fs::path folder = fs::path(output.second).parent_path();
  if (folder.empty())
  {
    folder = ".";
  }
  if (fs::is_directory(output.second, ec))
  {
    return output.first + " '" + output.second + "' is a folder: give a file name";
  }
  if (!fs::is_directory(folder, ec))
  {
    return output.first + " '" + output.second + "': the folder '" + folder.string() +
      "' does not exist: create it first";
  }
  if (access(folder.c_str(), W_OK) != 0)
  {
    return output.first + " '" + output.second + "': the folder '" + folder.string() +
      "' is not writable: choose another folder";
  }
  return std::string();
}
} // namespace

std::string outputPathsProblem(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs)
{
  for (size_t k = 0; k < outputs.size(); ++k)
  {
    const NamedPath& out = outputs[k];
    if (out.second.empty())
    {
      continue;
    }
    for (const NamedPath& in : inputs)
    {
      if (!in.second.empty() && sameFile(out.second, in.second))
      {
        return out.first + " '" + out.second + "' is the " + in.first +
          ": it would be overwritten; write the result to another file";
      }
    }
    for (size_t j = 0; j < k; ++j)
    {
      if (!outputs[j].second.empty() && sameFile(out.second, outputs[j].second))
      {
        return out.first + " and " + outputs[j].first + " both name '" + out.second +
          "': give each output its own file";
      }
    }
    const std::string folder = folderProblem(out);
    if (!folder.empty())
    {
      return folder;
    }
  }
  return std::string();
}

} // namespace sltkcli
