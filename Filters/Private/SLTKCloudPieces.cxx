// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKCloudPieces.h"

#include "SLTKBridge.h"

#include "sltk/cloud/PointOwners.h"

#include "vtkAppendPolyData.h"
#include "vtkCharArray.h"
#include "vtkCommunicator.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace sltk
{
namespace vtkbridge
{

vtkSmartPointer<vtkPolyData> piecesWithPointData(
  vtkPointSet* piece, const Communicator& comm, std::set<std::string>* dropped)
{
  vtkNew<vtkPolyData> mine; // the points and their arrays, no cells
  if (piece && piece->GetNumberOfPoints() > 0)
  {
    mine->SetPoints(piece->GetPoints());
    mine->GetPointData()->ShallowCopy(piece->GetPointData());
  }
  vtkNew<vtkCharArray> bytes;
  vtkCommunicator::MarshalDataObject(mine, bytes);
  std::vector<unsigned char> all;
  std::vector<std::int64_t> counts;
  comm.allGatherV(bytes->GetPointer(0), static_cast<size_t>(bytes->GetNumberOfValues()), all, counts);
  vtkNew<vtkAppendPolyData> append;
  std::int64_t offset = 0;
  for (const std::int64_t count : counts)
  {
    vtkNew<vtkCharArray> received;
    received->SetArray(reinterpret_cast<char*>(all.data() + offset), count, 1); // not owned: `all` outlives it
    offset += count;
    vtkNew<vtkPolyData> other;
    vtkCommunicator::UnMarshalDataObject(received, other);
    if (other->GetNumberOfPoints() > 0)
    {
      append->AddInputData(other);
      for (int a = 0; dropped && a < other->GetPointData()->GetNumberOfArrays(); ++a)
      {
        const char* name = other->GetPointData()->GetArrayName(a);
        dropped->insert(name ? name : "");
      }
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    result->ShallowCopy(append->GetOutput());
  }
  for (int a = 0; dropped && a < result->GetPointData()->GetNumberOfArrays(); ++a)
  {
    const char* name = result->GetPointData()->GetArrayName(a);
    dropped->erase(name ? name : ""); // kept: what is left was dropped
  }
  return result;
}

void distanceToShares(vtkPointSet* share, std::int64_t firstId, vtkPolyData* surface, double radius,
  const Communicator& comm, const Context& ctx, std::int64_t round)
{
  PointCloud<3> points;
  const vtkIdType count = share ? share->GetNumberOfPoints() : 0;
  points.Points.resize(static_cast<size_t>(count));
  for (vtkIdType k = 0; k < count; ++k)
  {
    share->GetPoint(k, points.Points[static_cast<size_t>(k)].data());
  }
  OwnedPoints<3> owned;
  const Status sent = sendToOwners(points, firstId, balancedCuts(points, comm), 0.0, comm, owned);
  points = PointCloud<3>();
  const std::int64_t vertices = surface ? surface->GetNumberOfPoints() : 0;
  const std::int64_t each = std::max<std::int64_t>(1, round / comm.size()); // a rank's vertices a round
  const std::int64_t rounds = comm.allReduce((vertices + each - 1) / each, ReduceOp::Max);
  if (!sent.isOk() || comm.allReduce(owned.Owned, ReduceOp::Sum) == 0 || rounds == 0)
  {
    return; // no point or no vertex anywhere (sendToOwners fails on every rank alike)
  }
  const NearestOverRanks<3> nearest(owned); // one locator for every round
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("DistanceToCloud");
  distance->SetNumberOfTuples(vertices);
  std::vector<double> found;
  std::vector<std::int64_t> ids;
  for (std::int64_t r = 0; r < rounds; ++r)
  {
    const std::int64_t begin = std::min(vertices, r * each), end = std::min(vertices, begin + each);
    std::vector<std::array<double, 3>> mine(static_cast<size_t>(end - begin));
    for (std::int64_t k = begin; k < end; ++k)
    {
      surface->GetPoint(k, mine[static_cast<size_t>(k - begin)].data());
    }
    std::vector<std::int64_t> before;
    const std::vector<std::array<double, 3>> queries = comm.allGatherV(mine, &before);
    nearest.find(queries, radius, comm, ctx, found, ids);
    std::int64_t at = 0; // this rank's first query in `queries`
    for (int q = 0; q < comm.rank(); ++q)
    {
      at += before[static_cast<size_t>(q)];
    }
    for (std::int64_t k = begin; k < end; ++k)
    {
      distance->SetValue(k, found[static_cast<size_t>(at + k - begin)]);
    }
  }
  if (vertices > 0)
  {
    surface->GetPointData()->AddArray(distance);
  }
}

} // namespace vtkbridge
} // namespace sltk
