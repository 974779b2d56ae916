// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TextCloudFile.h
/// The one reading of text point clouds (.xyz .txt .csv .pts), on one rank or
/// split over the ranks (CloudFileShares.h). vtkSLPointCloudReader (ParaView)
/// and the CLI both read through it (Filters/Private/SLTKTextCloud.h), so they
/// accept the same files and refuse the others with the same messages, on any
/// number of ranks.

#include "sltk/cloud/CloudFileShares.h"
#include "sltk/core/Status.h"
#include "sltk/exec/Communicator.h"

#include <string>

namespace sltk
{

/// The checks of any cloud file before a reader opens it, in this order: a
/// folder ("'<path>' is a folder: ..."), a file that cannot be opened
/// ("cannot open '<path>': ..."), an empty file ("'<path>' is empty (0 bytes): ...").
Status checkCloudFile(const std::string& path);

/// Collective. This rank's share of the points of a text cloud, in double: on
/// each line the first three numbers, separated by spaces, tabs, commas or
/// semicolons (further columns, such as normals, are ignored). Blank lines and
/// lines starting with '#' or '/' are skipped, and so is one header line (no
/// number) before the first point. A first line holding one whole number is a
/// count (Leica .pts): the file must then hold that many points ("its first
/// line announces N points..."). A NUL byte, a token that is not a number among
/// the first three, or fewer than three numbers fails with "<path>:<line>: ...".
/// A file of comments has no points and is read.
///
/// Every rank reads the lines before the first point (the header and the count
/// are decided there), then its share of the bytes from the first point on,
/// cut at line ends (CloudFileShares.h). Every rank returns the same status: the
/// first bad line of the file, with its line number, whichever rank read it;
/// `share` is complete only on success. On one rank (serialCommunicator()) the
/// share is the whole file. Run checkCloudFile first: this one does not look for
/// folders or empty files.
Status readTextCloudShare(const std::string& path, const Communicator& comm, CloudShare& share);

} // namespace sltk
