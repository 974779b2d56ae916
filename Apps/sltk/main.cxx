// SPDX-License-Identifier: BSD-3-Clause
// sltk: the Semi-Lagrangian level-set ToolKit from a terminal.
#include "Commands.h"

#include <vtkLogger.h>

#include <cstdlib>
#include <iostream>

namespace
{
const char* usage = R"(usage: sltk <command> [options]

commands:
  info CLOUD        validate a point cloud and print its size, bounds, spacing h_P
                    and the grid of every run of the reconstruction (thesis (4.36))
  reconstruct CLOUD reconstruct a watertight surface (signed distance + surface)
  hjb               solve a Hamilton-Jacobi-Bellman problem (thesis ch. 3)

Run `sltk <command> --help` for the options of a command.
Clouds: .ply .xyz .txt .csv .pts .obj .vtp .vtu .vtk
)";
} // namespace

int main(int argc, char** argv)
{
  // Errors reach the user once, through the commands' own messages.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  sltkcli::Args args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    std::cout << usage;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version")
  {
    std::cout << "sltk " << SLTK_VERSION << "\n";
    return 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  if (command == "info")
  {
    return sltkcli::commandInfo(args);
  }
  if (command == "reconstruct")
  {
    return sltkcli::commandReconstruct(args);
  }
  if (command == "hjb")
  {
    return sltkcli::commandHjb(args);
  }
  std::cerr << "sltk: unknown command '" << command << "'\n" << usage;
  return 2;
}
