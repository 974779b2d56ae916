// SPDX-License-Identifier: BSD-3-Clause
#include "Commands.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>

namespace sltkcli
{

std::string withMergedScanHint(const std::string& message, size_t points, bool thinned)
{
  constexpr size_t manyPoints = 100000; // a single laser scan of an object rarely has more
  if (thinned || points < manyPoints || message.find("use C_dx >=") == std::string::npos)
  {
    return message;
  }
  return message +
    ". If the cloud merges overlapping range scans, their overlaps make h_P tiny: try "
    "--remove-outliers --thin 2.5 (README, merged scans), then sltk info with the same options";
}

bool parseInitialGuess(const std::string& name, sltk::InitialGuess& guess)
{
  const char* names[3] = { "outside", "sphere", "ellipsoid" }; // InitialGuess values 0, 1, 2
  for (int k = 0; k < 3; ++k)
  {
    if (name == names[k])
    {
      guess = static_cast<sltk::InitialGuess>(k);
      return true;
    }
  }
  return false;
}

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
    const size_t equals = a.find('=');
    const std::string name = a.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    if (equals != std::string::npos && std::find(valued.begin(), valued.end(), name) != valued.end())
    {
      this->Values.emplace_back(name, a.substr(equals + 1)); // --name=value
    }
    else if (std::find(flags.begin(), flags.end(), name) != flags.end())
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

namespace
{
/// The whole of `text` as a finite number.
bool parseNumber(const std::string& text, double& v)
{
  try
  {
    size_t used = 0;
    v = std::stod(text, &used);
    return used == text.size() && std::isfinite(v);
  }
  catch (const std::exception&)
  {
    return false;
  }
}
} // namespace

double Options::number(const std::string& name, double fallback)
{
  if (!this->has(name))
  {
    return fallback;
  }
  const std::string text = this->value(name);
  double v = 0.0;
  if (!parseNumber(text, v))
  {
    if (this->Error.empty())
    {
      this->Error = "option --" + name + " expects a number, got '" + text + "'";
    }
    return fallback;
  }
  return v;
}

std::vector<double> Options::numbers(
  const std::string& name, size_t minCount, size_t maxCount, const std::vector<double>& fallback)
{
  if (!this->has(name))
  {
    return fallback;
  }
  const std::string text = this->value(name);
  std::vector<double> values;
  size_t begin = 0;
  bool good = true;
  while (good)
  {
    const size_t comma = text.find(',', begin);
    double v = 0.0;
    good = parseNumber(text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin), v);
    values.push_back(v);
    if (comma == std::string::npos)
    {
      break;
    }
    begin = comma + 1;
  }
  if (!good || values.size() < minCount || values.size() > maxCount)
  {
    if (this->Error.empty())
    {
      this->Error = "option --" + name + " expects " + std::to_string(minCount) +
        (maxCount > minCount ? " to " + std::to_string(maxCount) : std::string()) + " comma-separated numbers, got '" +
        text + "'";
    }
    return fallback;
  }
  return values;
}

} // namespace sltkcli
