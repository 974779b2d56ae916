// SPDX-License-Identifier: BSD-3-Clause
// sltk: the Semi-Lagrangian level-set ToolKit from a terminal.
#include "CliOptions.h"
#include "Commands.h"
#include "MpiSession.h"

#include <vtkLogger.h>

#include <iostream>
#include <memory>
#include <new>
#include <regex>
#include <sstream>
#include <vector>

namespace
{
/// CLI11's help, listing each command by the first paragraph of its description.
class Formatter : public CLI::Formatter
{
public:
  std::string make_subcommand(const CLI::App* sub) const override
  {
    const std::string& description = sub->get_description();
    std::stringstream out;
    CLI::detail::format_help(
      out, sub->get_display_name(true), description.substr(0, description.find("\n\n")), this->column_width_);
    return out.str();
  }
};
} // namespace

int main(int argc, char** argv)
{
  // Errors reach the user once, through the commands' own messages.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const sltkcli::MpiSession mpi(&argc, &argv); // under mpirun: the ranks the filters split their work over
  CLI::App sltk("sltk: the Semi-Lagrangian level-set ToolKit (Preda 2024)\n", "sltk");
  sltk.set_version_flag("--version", "sltk " SLTK_VERSION);
  sltk.require_subcommand(1);
  sltk.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast); // a repeated option: the last
  sltk.formatter(std::make_shared<Formatter>());
  sltk.get_formatter()->column_width(26);
  sltk.get_formatter()->label("SUBCOMMAND", "COMMAND");
  sltk.footer("Run `sltk <command> --help` for the options of a command.\n"
              "Clouds: .ply .xyz .txt .csv .pts .obj .vtp .vtu .vtk\n"
              "Exit status: 0 done, 1 failed, 2 bad usage or input, 3 reconstructed but the result does not fit "
              "the cloud (its files are written)");
  const std::vector<sltkcli::Command> commands = { sltkcli::addInfoCommand(sltk), sltkcli::addReconstructCommand(sltk),
    sltkcli::addHjbCommand(sltk) };
  for (const sltkcli::Command& command : commands)
  {
    command.Parser->group("Commands");
  }
  if (argc < 2)
  {
    std::cout << sltk.help();
    return 2;
  }
  try
  {
    sltk.parse(argc, argv);
  }
  catch (const CLI::Success& e) // --help, --version
  {
    return sltk.exit(e);
  }
  catch (const CLI::ParseError& e)
  {
    const auto chosen = sltk.get_subcommands();
    if (chosen.empty() && argv[1][0] != '-')
    {
      std::vector<std::string> names;
      for (const sltkcli::Command& command : commands)
      {
        names.push_back(command.Parser->get_name());
      }
      return sltkcli::fail(
        std::string("unknown command '") + argv[1] + "': use " + sltk::orList(names) + " (see sltk --help)", 2);
    }
    // CLI11 says "--cdx: 1 required FLOAT missing" when an option ends the command line.
    static const std::regex missing("(\\S+): [0-9]+ required \\S* ?missing");
    std::smatch option;
    const std::string what = e.what();
    const std::string message = std::regex_match(what, option, missing) ? option[1].str() + ": needs a value" : what;
    const std::string help = chosen.empty() ? "sltk --help" : "sltk " + chosen[0]->get_name() + " --help";
    return sltkcli::fail(message + " (see " + help + ")", 2);
  }
  for (const sltkcli::Command& command : commands)
  {
    if (command.Parser->parsed())
    {
      // No exception leaves sltk (Documentation/Architecture.md, "Errors, logging, interrupts"):
      // what the memory checks could not foresee ends the command with its error.
      try
      {
        return command.Run();
      }
      catch (const std::bad_alloc&)
      {
        return sltkcli::fail("out of memory: the command needs more memory than this machine can give; use a "
                             "coarser grid (fewer nodes, a larger --cdx) or a smaller problem",
          1);
      }
      catch (const std::exception& e)
      {
        return sltkcli::fail(std::string("internal error: ") + e.what(), 1);
      }
    }
  }
  return 2; // not reached: require_subcommand(1)
}
