// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKCloudPieces.h"

#include "vtkAppendPolyData.h"
#include "vtkCharArray.h"
#include "vtkCommunicator.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

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

} // namespace vtkbridge
} // namespace sltk
