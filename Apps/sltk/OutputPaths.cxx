// SPDX-License-Identifier: BSD-3-Clause
#include "OutputPaths.h"

#include "FileNames.h"

#include <algorithm>

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

std::string folderProblem(const OutputFile& output)
{
  std::error_code ec;
  fs::path folder = fs::path(output.Path).parent_path();
  if (folder.empty())
  {
    folder = ".";
  }
  if (fs::is_directory(output.Path, ec))
  {
    return output.Option + " '" + output.Path + "' is a folder: give a file name";
  }
  if (!fs::is_directory(folder, ec))
  {
    return output.Option + " '" + output.Path + "': the folder '" + folder.string() +
      "' does not exist: create it first";
  }
  if (access(folder.c_str(), W_OK) != 0)
  {
    return output.Option + " '" + output.Path + "': the folder '" + folder.string() +
      "' is not writable: choose another folder";
  }
  return std::string();
}

std::string extensionProblem(const OutputFile& output)
{
  const std::vector<std::string>& allowed = output.Extensions;
  if (allowed.empty() || std::find(allowed.begin(), allowed.end(), extensionOf(output.Path)) != allowed.end())
  {
    return std::string();
  }
  std::string list;
  for (size_t k = 0; k < allowed.size(); ++k)
  {
    list += (k ? (k + 1 == allowed.size() ? " or ." : ", .") : ".") + allowed[k];
  }
  return output.Option + " '" + output.Path + "': the file written is " + list +
    "; give it that extension (the format is not chosen by this name)";
}
} // namespace

std::string outputPathsProblem(const std::vector<NamedPath>& inputs, const std::vector<OutputFile>& outputs)
{
  for (size_t k = 0; k < outputs.size(); ++k)
  {
    const OutputFile& out = outputs[k];
    if (out.Path.empty())
    {
      continue;
    }
    for (const NamedPath& in : inputs)
    {
      if (!in.second.empty() && sameFile(out.Path, in.second))
      {
        return out.Option + " '" + out.Path + "' is the " + in.first +
          ": it would be overwritten; write the result to another file";
      }
    }
    for (size_t j = 0; j < k; ++j)
    {
      if (!outputs[j].Path.empty() && sameFile(out.Path, outputs[j].Path))
      {
        return out.Option + " and " + outputs[j].Option + " both name '" + out.Path +
          "': give each output its own file";
      }
    }
    std::string problem = folderProblem(out);
    if (problem.empty())
    {
      problem = extensionProblem(out);
    }
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

} // namespace sltkcli
