// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadCloudShares.h
/// `mpirun sltk reconstruct CLOUD`: the cloud read in parallel
/// (Documentation/Distributed.md, "Reading the cloud"). Text clouds (.xyz .txt
/// .csv .pts) are cut into byte ranges at line ends and binary PLY files of
/// points alone into vertex records (sltk/cloud/PlyCloudFile.h, after the
/// serial reader's checks, CheckPly.h), each rank parsing its share; every
/// other file (.obj .vtp .vtu .vtk, ASCII PLY, PLY with normals, colours or
/// faces) is read whole by every rank through readPointCloud. Until points move
/// to the ranks that need them (issue 38), the ranks then all-gather the shares
/// in rank order, which is the file's order: every rank holds the cloud that
/// readPointCloud reads, the same points in the same order.

#include "sltk/core/Status.h"
#include "sltk/exec/CommTraffic.h"

#include <vtkPointSet.h>
#include <vtkSmartPointer.h>

#include <string>

namespace sltkcli
{

/// The points of the file and what the ranks read and hold (--json).
struct CloudReadCounts
{
  long long Total = 0;       ///< points_total: the points in the file
  long long ReadMax = 0;     ///< points_read_max: the most points a rank parsed from the file
  long long HeldMax = 0;     ///< points_held_max: the most points a rank holds after the read (today every point)
  double ParseSeconds = 0.0; ///< parse_seconds: the slowest rank's parse of its share (before the gather)
  /// read_traffic: the read's traffic (the checks' agreements, the gather), each count its busiest rank's
  sltk::CommTraffic Traffic;
};

/// Collective under mpirun (every rank calls it; every rank returns the same
/// status, the one-rank message of the first bad line). One rank: readPointCloud's cloud.
sltk::Status readCloudOnRanks(const std::string& path, vtkSmartPointer<vtkPointSet>& cloud, CloudReadCounts& counts);

} // namespace sltkcli
