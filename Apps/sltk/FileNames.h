// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FileNames.h
/// File-name helpers shared by the readers and writers of the CLI.

#include <string>

namespace sltkcli
{

/// The extension of `path` after its last dot, lower case ("" when none):
/// formats are chosen case-insensitively (SCAN.PLY reads as .ply).
std::string extensionOf(const std::string& path);

} // namespace sltkcli
