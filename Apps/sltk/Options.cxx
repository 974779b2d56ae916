// SPDX-License-Identifier: BSD-3-Clause
#include "Commands.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace sltkcli
{

int fail(const std::string& message, int code)
{
  std::cerr << "sltk: error: " << message << "\n";
  return code;
}

Options::Options(const Args& args, const std::vector<std::string>& valued, const std::vector<std::string>& flags)
{
  for (size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 || a == "--")
    {
      this->Positional.push_back(a);
      continue;
    }
    const std::string name = a.substr(2);
    if (std::find(flags.begin(), flags.end(), name) != flags.end())
    {
      this->Values.emplace_back(name, "");
    }
    else if (std::find(valued.begin(), valued.end(), name) != valued.end())
    {
      if (i + 1 >= args.size())
      {
        this->Error = "option --" + name + " needs a value";
        return;
      }
      this->Values.emplace_back(name, args[++i]);
    }
    else
    {
      this->Error = "unknown option " + a + " (see --help)";
      return;
    }
  }
}

bool Options::has(const std::string& name) const
{
  return std::any_of(this->Values.begin(), this->Values.end(), [&](const auto& v) { return v.first == name; });
}

std::string Options::value(const std::string& name, const std::string& fallback) const
{
  for (auto it = this->Values.rbegin(); it != this->Values.rend(); ++it)
  {
    if (it->first == name)
    {
      return it->second;
    }
  }
  return fallback;
}

double Options::number(const std::string& name, double fallback)
{
  if (!this->has(name))
  {
    return fallback;
  }
  const std::string text = this->value(name);
  try
  {
    size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(v))
    {
      throw std::invalid_argument(text);
    }
    return v;
  }
  catch (const std::exception&)
  {
    if (this->Error.empty())
    {
      this->Error = "option --" + name + " expects a number, got '" + text + "'";
    }
    return fallback;
  }
}

} // namespace sltkcli
