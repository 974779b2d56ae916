// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Json.h
/// A minimal JSON object writer for the CLI's `--json` summaries.

#include <sstream>
#include <string>
#include <vector>

namespace sltkcli
{

class JsonObject
{
public:
  JsonObject& add(const std::string& key, double value);
  JsonObject& add(const std::string& key, long long value);
  JsonObject& add(const std::string& key, const std::string& value);
  JsonObject& add(const std::string& key, const std::vector<long long>& values);
  JsonObject& add(const std::string& key, const std::vector<JsonObject>& objects);
  std::string str() const;

private:
  JsonObject& raw(const std::string& key, const std::string& json);
  std::vector<std::pair<std::string, std::string>> Fields;
};

} // namespace sltkcli
