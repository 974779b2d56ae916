// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file WriteAtomically.h
/// Output files appear whole or not at all: writers write to a temporary
/// name in the target directory, which is renamed once complete.

#include "sltk/core/Status.h"

#include <functional>
#include <string>

namespace sltkcli
{

/// Calls write(temporaryPath) and renames the result to `path` on success;
/// removes the temporary file on failure.
sltk::Status writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

/// Writes text to `path` atomically.
sltk::Status writeTextFile(const std::string& path, const std::string& text);

} // namespace sltkcli
