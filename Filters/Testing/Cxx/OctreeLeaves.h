// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The unmasked leaves of vtkOctreeSDF's hyper tree grid with their cell data,
// the one-rank reference they are compared with, and the MPI controller the
// tests run under (TestOctreeSDF.cxx, TestOctreeSDF2D.cxx).
#include "FilterTestCheck.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDummyController.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedGeometryCursor.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkSLLevelSetReconstruct.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace sltktest
{

struct Leaf
{
  int Level = 0;
  int Rank = 0;
  double Phi = 0.0;
  double Distance = 0.0;
  double Size = 0.0;
  std::array<double, 3> Centre{};
};

inline void collect(vtkHyperTreeGridNonOrientedGeometryCursor* cursor, vtkHyperTreeGrid* htg, std::vector<Leaf>& out)
{
  if (cursor->IsMasked())
  {
    return;
  }
  if (cursor->IsLeaf())
  {
    const vtkIdType id = cursor->GetGlobalNodeIndex();
    Leaf leaf;
    leaf.Level = static_cast<int>(htg->GetCellData()->GetArray("Level")->GetTuple1(id));
    leaf.Rank = static_cast<int>(htg->GetCellData()->GetArray("Rank")->GetTuple1(id));
    leaf.Phi = htg->GetCellData()->GetArray("SignedDistance")->GetTuple1(id);
    leaf.Distance = htg->GetCellData()->GetArray("DistanceToCloud")->GetTuple1(id);
    leaf.Size = cursor->GetSize()[0];
    check(leaf.Level == static_cast<int>(cursor->GetLevel()), "the Level array is the cell's level");
    for (int a = 0; a < 3; ++a)
    {
      leaf.Centre[a] = cursor->GetOrigin()[a] + 0.5 * cursor->GetSize()[a];
    }
    out.push_back(leaf);
    return;
  }
  for (unsigned char c = 0; c < cursor->GetNumberOfChildren(); ++c)
  {
    cursor->ToChild(c);
    collect(cursor, htg, out);
    cursor->ToParent();
  }
}

/// The unmasked leaves of `htg` (null or without the arrays: none).
inline std::vector<Leaf> leavesOf(vtkHyperTreeGrid* htg)
{
  std::vector<Leaf> leaves;
  if (!htg || !htg->GetCellData()->GetArray("SignedDistance") || !htg->GetCellData()->GetArray("Rank"))
  {
    return leaves;
  }
  vtkHyperTreeGrid::vtkHyperTreeGridIterator it;
  htg->InitializeTreeIterator(it);
  vtkIdType index = 0;
  vtkNew<vtkHyperTreeGridNonOrientedGeometryCursor> cursor;
  while (it.GetNextTree(index))
  {
    htg->InitializeNonOrientedGeometryCursor(cursor, index);
    collect(cursor, htg, leaves);
  }
  return leaves;
}

inline double fieldValue(vtkDataObject* data, const char* name, vtkIdType tuple = 0)
{
  vtkDataArray* a = data ? data->GetFieldData()->GetArray(name) : nullptr;
  return a && tuple < a->GetNumberOfTuples() ? a->GetTuple1(tuple) : std::nan("");
}

/// The MPI controller of a test's main(), this rank and the number of ranks.
struct MpiRun
{
  vtkSmartPointer<vtkMPIController> Controller;
  int Rank = 0;
  int Size = 1;
};

/// Initialises MPI with main's arguments and makes its controller the global
/// one (the filters' communicator); main clears it and finalises at the end.
inline MpiRun startMpi(int* argc, char*** argv)
{
  MpiRun run;
  run.Controller = vtkSmartPointer<vtkMPIController>::New();
  run.Controller->Initialize(argc, argv);
  vtkMultiProcessController::SetGlobalController(run.Controller);
  run.Rank = run.Controller->GetLocalProcessId();
  run.Size = run.Controller->GetNumberOfProcesses();
  return run;
}

/// Runs `filter` (its other properties set) on `input` on this rank alone
/// (vtkDummyController) with one thread, the reference of a run on several
/// ranks: whether it succeeded.
inline bool updateAlone(vtkSLLevelSetReconstruct* filter, vtkDataObject* input)
{
  vtkNew<vtkDummyController> alone;
  filter->SetController(alone);
  filter->SetInputDataObject(input);
  filter->SetNumberOfThreads(1);
  return filter->GetExecutive()->Update() == 1;
}

/// How `leaves` agree with `reference`'s leaves at the same centre and size:
/// how many have none, and the largest |SignedDistance difference| / `cell`.
struct LeafAgreement
{
  long long Missing = 0;
  double WorstInCells = 0.0;
};

inline LeafAgreement agreement(const std::vector<Leaf>& leaves, const std::vector<Leaf>& reference, double cell)
{
  std::map<std::array<double, 4>, double> phiAt;
  for (const Leaf& leaf : reference)
  {
    phiAt[{ leaf.Centre[0], leaf.Centre[1], leaf.Centre[2], leaf.Size }] = leaf.Phi;
  }
  LeafAgreement result;
  for (const Leaf& leaf : leaves)
  {
    const auto at = phiAt.find({ leaf.Centre[0], leaf.Centre[1], leaf.Centre[2], leaf.Size });
    if (at == phiAt.end())
    {
      ++result.Missing;
      continue;
    }
    result.WorstInCells = std::max(result.WorstInCells, std::abs(leaf.Phi - at->second) / cell);
  }
  return result;
}

} // namespace sltktest
