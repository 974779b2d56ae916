// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file BenchCli.h
/// The benchmarks' command line: CLI11 with one error policy (the message and
/// a pointer to --help on stderr, exit code 2; --help prints the options and
/// exits with 0) and comma-separated lists.

#include <CLI/CLI.hpp>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace sltkbench
{

/// An application whose options keep the last of repeated values (as the
/// benchmarks' hand-written parsers did); list options opt into TakeAll.
inline void takeLastByDefault(CLI::App& app)
{
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

/// Parses argv into `app`'s options. Returns the exit code when the program
/// must stop (--help: 0, a bad command line: 2), nothing when it may run.
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv)
{
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return std::nullopt;
}

/// The non-empty items of a comma-separated list.
inline std::vector<std::string> splitList(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
  {
    if (!item.empty())
    {
      out.push_back(item);
    }
  }
  return out;
}

} // namespace sltkbench
