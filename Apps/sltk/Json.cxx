// SPDX-License-Identifier: BSD-3-Clause
#include "Json.h"

#include <cmath>
#include <iomanip>

namespace sltkcli
{

namespace
{
std::string quote(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    switch (c)
    {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      default:
        out += c;
    }
  }
  return out + "\"";
}
} // namespace

JsonObject& JsonObject::raw(const std::string& key, const std::string& json)
{
  this->Fields.emplace_back(key, json);
  return *this;
}

JsonObject& JsonObject::add(const std::string& key, double value)
{
  if (!std::isfinite(value))
  {
    return this->raw(key, "null");
  }
  std::ostringstream os;
  os << std::setprecision(17) << value;
  return this->raw(key, os.str());
}

JsonObject& JsonObject::add(const std::string& key, long long value)
{
  return this->raw(key, std::to_string(value));
}

JsonObject& JsonObject::add(const std::string& key, const std::string& value)
{
  return this->raw(key, quote(value));
}

JsonObject& JsonObject::add(const std::string& key, const std::vector<long long>& values)
{
  std::string s = "[";
  for (size_t i = 0; i < values.size(); ++i)
  {
    s += (i ? ", " : "") + std::to_string(values[i]);
  }
  return this->raw(key, s + "]");
}

JsonObject& JsonObject::add(const std::string& key, const std::vector<JsonObject>& objects)
{
  std::string s = "[";
  for (size_t i = 0; i < objects.size(); ++i)
  {
    s += (i ? ", " : "") + objects[i].str();
  }
  return this->raw(key, s + "]");
}

std::string JsonObject::str() const
{
  std::string s = "{";
  for (size_t i = 0; i < this->Fields.size(); ++i)
  {
    s += (i ? ", " : "") + quote(this->Fields[i].first) + ": " + this->Fields[i].second;
  }
  return s + "}";
}

} // namespace sltkcli
