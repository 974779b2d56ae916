// SPDX-License-Identifier: BSD-3-Clause
#include "ReadCloudShares.h"

#include "CheckPly.h"
#include "FileNames.h"
#include "ReadPointCloud.h"
#include "SLTKCommunicator.h"

#include "sltk/cloud/CloudPieces.h"
#include "sltk/cloud/PlyCloudFile.h"
#include "sltk/cloud/TextCloudFile.h"
#include "sltk/exec/CountingCommunicator.h"
#include "sltk/exec/FirstError.h"

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkType.h>

#include <chrono>
#include <fstream>
#include <limits>
#include <memory>

namespace sltkcli
{

namespace
{
/// Whether every rank finds `path` a binary PLY of points alone (PlyCloudFile.h), with its layout.
/// Such a file passes the serial reader's checks first (CheckPly.h), with their messages, in `status`.
bool splitPly(
  const std::string& path, const sltk::Communicator& comm, sltk::PlyVertexLayout& layout, sltk::Status& status)
{
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::int64_t bytes = static_cast<std::int64_t>(in.tellg());
  in.seekg(0);
  const bool mine = in && sltk::plyVertexLayout(in, bytes, layout);
  if (comm.anyRank(!mine))
  {
    return false;
  }
  status = sltk::agreeOnFirstError(comm, checkPlyFile(path));
  return true;
}

/// The cloud from every rank's share, in rank order (the file's order), or with
/// `keep` this rank's share alone, in the point type of the serial reader:
/// double for text and wide PLY coordinates, else float.
vtkSmartPointer<vtkPointSet> cloudOfShares(sltk::CloudShare& share, bool keep, const sltk::Communicator& comm, int type)
{
  std::vector<std::array<double, 3>> all =
    comm.size() > 1 && !keep ? comm.allGatherV(share.Points) : std::move(share.Points);
  share.Points = {};
  vtkNew<vtkPoints> points;
  points->SetDataType(type);
  points->SetNumberOfPoints(static_cast<vtkIdType>(all.size()));
  for (size_t i = 0; i < all.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), all[i].data());
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  return cloud;
}

/// The bounds of every rank's `cloud` (vtkDataSet::GetBounds over the ranks; inverted
/// when no rank has a point). Collective.
std::array<double, 6> boundsOverRanks(vtkPointSet* cloud, const sltk::Communicator& comm)
{
  std::array<double, 3> low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  if (cloud && cloud->GetNumberOfPoints() > 0)
  {
    double b[6];
    cloud->GetBounds(b);
    for (int a = 0; a < 3; ++a)
    {
      low[a] = b[2 * a];
      high[a] = b[2 * a + 1];
    }
  }
  comm.allReduce(low.data(), 3, sltk::ReduceOp::Min);
  comm.allReduce(high.data(), 3, sltk::ReduceOp::Max);
  return { low[0], high[0], low[1], high[1], low[2], high[2] };
}
} // namespace

sltk::Status readCloudOnRanks(
  const std::string& path, bool whole, vtkSmartPointer<vtkPointSet>& cloud, CloudReadCounts& counts)
{
  cloud = nullptr;
  counts = CloudReadCounts();
  std::unique_ptr<sltk::Communicator> ranks;
  SLTK_RETURN_IF_ERROR(sltk::vtkbridge::makeCommunicator(nullptr, ranks));
  const sltk::CountingCommunicator counted(*ranks);
  const sltk::Communicator* comm = &counted; // the read's traffic: counts.Traffic
  SLTK_RETURN_IF_ERROR(sltk::agreeOnFirstError(*comm, sltk::checkCloudFile(path)));
  const std::string ext = extensionOf(path);
  const bool text = isTextCloudExtension(ext);
  sltk::PlyVertexLayout layout;
  sltk::Status checked;
  if (!text && !(ext == "ply" && splitPly(path, *comm, layout, checked)))
  {
    const sltk::Status read = readPointCloud(path, cloud); // every rank the whole file, as before
    counts.Total = counts.ReadMax = counts.HeldMax = read.isOk() ? cloud->GetNumberOfPoints() : 0;
    counts.Bounds = boundsOverRanks(read.isOk() ? cloud.Get() : nullptr, *comm);
    counts.Traffic = sltk::busiestRanks({ counted.traffic() }, *ranks)[0]; // uncounted
    return read;
  }
  SLTK_RETURN_IF_ERROR(checked);
  sltk::CloudShare share;
  const auto start = std::chrono::steady_clock::now();
  SLTK_RETURN_IF_ERROR(
    text ? sltk::readTextCloudShare(path, *comm, share) : sltk::readPlyCloudShare(path, layout, *comm, share));
  counts.ParseSeconds = comm->allReduce(
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), sltk::ReduceOp::Max);
  counts.Total = share.Total;
  counts.ReadMax = comm->allReduce(static_cast<std::int64_t>(share.Points.size()), sltk::ReduceOp::Max);
  // Shares identical on every rank (a file that repeats itself, split at the repeat) would be
  // taken by the filter for the whole cloud given to every rank: those are gathered.
  sltk::PointCloud<3> mine{ std::move(share.Points) };
  counts.Shares = !whole && comm->size() > 1 && !sltk::sameCloudOnEveryRank(mine, *comm);
  share.Points = std::move(mine.Points);
  cloud = cloudOfShares(share, counts.Shares, *comm, text || layout.Wide ? VTK_DOUBLE : VTK_FLOAT);
  counts.Bounds = boundsOverRanks(cloud, *comm);
  counts.HeldMax = comm->allReduce(static_cast<std::int64_t>(cloud->GetNumberOfPoints()), sltk::ReduceOp::Max);
  counts.Traffic = sltk::busiestRanks({ counted.traffic() }, *ranks)[0]; // uncounted
  return sltk::Status::ok();
}

} // namespace sltkcli
