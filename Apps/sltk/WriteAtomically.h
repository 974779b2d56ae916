// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file WriteAtomically.h
/// Output files appear whole or not at all: writers write to a temporary
/// name in the target directory, which is renamed once complete.

#include "sltk/core/Status.h"

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <string>
#include <vector>

namespace sltkcli
{

/// Calls write(temporaryPath) and renames the result to `path` on success;
/// removes the temporary file on failure.
sltk::Status writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

/// Files, then folders (emptied by then), to remove if SIGINT or SIGTERM
/// arrives (at most 4 of each); empty lists clear them. writeAtomically()
/// registers its temporary file this way.
void setPendingPaths(const std::vector<std::string>& files, const std::vector<std::string>& folders);

/// Writes text to `path` atomically.
sltk::Status writeTextFile(const std::string& path, const std::string& text);

/// Writes `value` to `path` atomically as JSON (indented; non-finite numbers as null,
/// text that is not UTF-8, e.g. a file name, with U+FFFD in place of its invalid bytes).
sltk::Status writeJsonFile(const std::string& path, const nlohmann::ordered_json& value);

} // namespace sltkcli
