// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReadCloudShares.h
/// `mpirun sltk reconstruct CLOUD`: the cloud read in parallel
/// (Documentation/Distributed.md, "Reading the cloud"). Text clouds (.xyz .txt
/// .csv .pts) are cut into byte ranges at line ends and binary PLY files of
/// points alone into vertex records (sltk/cloud/PlyCloudFile.h, after the
/// serial reader's checks, CheckPly.h), each rank parsing its share; every
/// other file (.obj .vtp .vtu .vtk, ASCII PLY, PLY with normals, colours or
/// faces) is read whole by every rank through readPointCloud. A rank then keeps
/// its share (the shares in rank order are the file's order), which
/// vtkSLLevelSetReconstruct plans on where it is (CloudPiecesAreShares), or,
/// when the whole cloud is wanted (--png draws it), the ranks all-gather the
/// shares: every rank holds the cloud that readPointCloud reads, the same
/// points in the same order.

#include "sltk/core/Status.h"
#include "sltk/exec/CommTraffic.h"

#include <vtkPointSet.h>
#include <vtkSmartPointer.h>

#include <array>
#include <string>

namespace sltkcli
{

/// The points of the file and what the ranks read and hold (--json).
struct CloudReadCounts
{
  long long Total = 0;   ///< points_total: the points in the file
  long long ReadMax = 0; ///< points_read_max: the most points a rank parsed from the file
  long long HeldMax = 0; ///< the most points a rank holds after the read: its share, or every point
  bool Shares = false;   ///< each rank holds its share of the file (in rank order), not the whole cloud
  /// The cloud's bounds over every rank (vtkDataSet::GetBounds's layout; inverted when it has no point).
  std::array<double, 6> Bounds{ 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  double ParseSeconds = 0.0; ///< parse_seconds: the slowest rank's parse of its share
  /// read_traffic: the read's traffic (the checks' agreements, the gather), each count its busiest rank's
  sltk::CommTraffic Traffic;
};

/// Collective under mpirun (every rank calls it; every rank returns the same
/// status, the one-rank message of the first bad line). One rank, or `whole`:
/// readPointCloud's cloud on every rank; else, for a file read in shares, this
/// rank's share (counts.Shares).
sltk::Status readCloudOnRanks(
  const std::string& path, bool whole, vtkSmartPointer<vtkPointSet>& cloud, CloudReadCounts& counts);

} // namespace sltkcli
