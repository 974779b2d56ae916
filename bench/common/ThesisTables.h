// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ThesisTables.h
/// The thesis's numbers as transcribed in thesis_tables.json (one object per
/// table, e.g. "table_4_2_circle_64pts": { "Q1": { "l1": [...] } }), read with
/// nlohmann-json. A missing or malformed file leaves the tables empty:
/// loaded() is false and every look-up finds nothing. The file lies outside
/// the repository: the benchmarks take its path with --tables (default
/// DefaultThesisTablesPath) and print '-' (formatValue) for what they miss.

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sltkbench
{

/// Where the benchmarks look for thesis_tables.json unless told (--tables).
inline constexpr const char* DefaultThesisTablesPath = "/work/shared/reference/thesis_tables.json";

/// `value` printed with the printf format `format` (one double), or "-"
/// right-aligned in the width of that format when it is NaN (a thesis value
/// the tables do not have, an order without a previous row).
inline std::string formatValue(double value, const char* format = "%9.3e")
{
  char buf[64];
  if (std::isnan(value))
  {
    const int width = std::snprintf(buf, sizeof buf, format, 0.0);
    return std::string(static_cast<size_t>(width > 1 ? width - 1 : 0), ' ') + "-";
  }
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

class ThesisTables
{
public:
  explicit ThesisTables(const std::string& path)
  {
    std::ifstream in(path);
    if (in)
    {
      this->Root = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    }
  }

  bool loaded() const { return this->Root.is_object(); }

  /// The entry at a path of keys ({ "table_4_2_circle_64pts", "Q1", "l1" }), or nullptr.
  const nlohmann::json* find(const std::vector<std::string>& keys) const
  {
    const nlohmann::json* node = &this->Root;
    for (const std::string& key : keys)
    {
      if (!node->is_object() || !node->contains(key))
      {
        return nullptr;
      }
      node = &(*node)[key];
    }
    return node;
  }

  /// The same with the keys in one '/'-separated string ("table_4_2_circle_64pts/Q1/l1").
  const nlohmann::json* find(const std::string& path) const
  {
    std::vector<std::string> keys;
    std::stringstream in(path);
    std::string key;
    while (std::getline(in, key, '/'))
    {
      keys.push_back(key);
    }
    return this->find(keys);
  }

  /// The entry of `field` ("WENO", "CWENO/l1", a '/'-separated path below
  /// `table`) in the row of `table` whose "N" is `n`; NaN when absent.
  double valueAtN(const std::string& table, const std::string& field, long long n) const
  {
    const nlohmann::json* ns = this->find(table + "/N");
    const nlohmann::json* values = this->find(table + "/" + field);
    if (!ns || !values || !ns->is_array() || !values->is_array())
    {
      return std::nan("");
    }
    for (size_t k = 0; k < ns->size() && k < values->size(); ++k)
    {
      if ((*ns)[k].is_number() && static_cast<long long>((*ns)[k].get<double>()) == n)
      {
        return (*values)[k].is_number() ? (*values)[k].get<double>() : std::nan("");
      }
    }
    return std::nan("");
  }

  /// The entries at `keys` as text (an array's items, or the single scalar):
  /// strings as they are, other values as JSON text; empty when absent.
  std::vector<std::string> texts(const std::vector<std::string>& keys) const
  {
    std::vector<std::string> out;
    for (const nlohmann::json* item : items(this->find(keys)))
    {
      out.push_back(item->is_string() ? item->get<std::string>() : item->dump());
    }
    return out;
  }

  /// The entries at `keys` as numbers, NaN for an entry that is not a number.
  std::vector<double> numbers(const std::vector<std::string>& keys) const
  {
    std::vector<double> out;
    for (const nlohmann::json* item : items(this->find(keys)))
    {
      out.push_back(item->is_number() ? item->get<double>() : std::nan(""));
    }
    return out;
  }

private:
  static std::vector<const nlohmann::json*> items(const nlohmann::json* node)
  {
    std::vector<const nlohmann::json*> out;
    if (node && node->is_array())
    {
      for (const auto& item : *node)
      {
        out.push_back(&item);
      }
    }
    else if (node && !node->is_object())
    {
      out.push_back(node);
    }
    return out;
  }

  nlohmann::json Root; // null until a file is parsed; discarded on a syntax error
};

} // namespace sltkbench
