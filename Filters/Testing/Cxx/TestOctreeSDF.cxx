// SPDX-License-Identifier: GPL-2.0-or-later
// vtkOctreeSDF's vtkHyperTreeGrid against the forest it comes from
// (Octree/include/sltk/octree/CloudForest.h), serially and under
// `mpiexec -n 2` with every point on rank 0: this rank's unmasked leaves are
// its forest leaves (count, level, rank, distance), each at the right place
// (the distance from the HTG cell's centre to the cloud by brute force), the
// ranks' leaves add up to the forest, and the .htg file written and read back
// holds the same cells. Usage: sltkFiltersOctreeTests OUTPUT_DIR
#include "FilterTestCheck.h"
#include "SLTKCommunicator.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "sltk/octree/CloudForest.h"
#include "vtkOctreeSDF.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedGeometryCursor.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLHyperTreeGridReader.h"
#include "vtkXMLHyperTreeGridWriter.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using sltktest::check;

struct HtgLeaf
{
  int Level;
  double Distance;
  int Rank;
  std::array<double, 3> Centre;
};

void collect(
  vtkHyperTreeGridNonOrientedGeometryCursor* cursor, vtkHyperTreeGrid* htg, std::vector<HtgLeaf>& out, int& masked)
{
  if (cursor->IsMasked())
  {
    ++masked;
    return;
  }
  if (cursor->IsLeaf())
  {
    const vtkIdType id = cursor->GetGlobalNodeIndex();
    HtgLeaf leaf{};
    leaf.Level = static_cast<int>(htg->GetCellData()->GetArray("Level")->GetTuple1(id));
    leaf.Distance = htg->GetCellData()->GetArray("DistanceToCloud")->GetTuple1(id);
    leaf.Rank = static_cast<int>(htg->GetCellData()->GetArray("Rank")->GetTuple1(id));
    check(leaf.Level == static_cast<int>(cursor->GetLevel()), "Level array is the cell's level");
    for (int a = 0; a < 3; ++a)
    {
      leaf.Centre[a] = cursor->GetOrigin()[a] + 0.5 * cursor->GetSize()[a];
    }
    out.push_back(leaf);
    return;
  }
  for (unsigned char c = 0; c < 8; ++c)
  {
    cursor->ToChild(c);
    collect(cursor, htg, out, masked);
    cursor->ToParent();
  }
}

std::vector<HtgLeaf> unmaskedLeaves(vtkHyperTreeGrid* htg, int& masked)
{
  std::vector<HtgLeaf> leaves;
  masked = 0;
  vtkHyperTreeGrid::vtkHyperTreeGridIterator it;
  htg->InitializeTreeIterator(it);
  vtkIdType index = 0;
  vtkNew<vtkHyperTreeGridNonOrientedGeometryCursor> cursor;
  while (it.GetNextTree(index))
  {
    htg->InitializeNonOrientedGeometryCursor(cursor, index);
    collect(cursor, htg, leaves, masked);
  }
  return leaves;
}
} // namespace

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId(), size = controller->GetNumberOfProcesses();
  const std::string outDir = argc > 1 ? argv[1] : ".";

  // An ellipsoid cloud (semi-axes 1, 0.5, 0.5 around (2, 1, -1)) on rank 0; the other ranks have none.
  sltk::PointCloud<3> cloud = sltk::sphereCloud(1500, 0.5, { 2.0, 1.0, -1.0 });
  for (auto& p : cloud.Points)
  {
    p[0] = 2.0 + 2.0 * (p[0] - 2.0);
  }
  const sltk::PointCloud<3> mine = rank == 0 ? cloud : sltk::PointCloud<3>{};
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble(); // the forest below gets the same coordinates
  for (const auto& p : mine.Points)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);

  vtkNew<vtkOctreeSDF> filter;
  filter->SetInputDataObject(input);
  filter->SetMinimumLevel(1);
  filter->SetMaximumLevel(4);
  filter->SetNumberOfThreads(1);
  filter->Update();
  vtkHyperTreeGrid* htg = filter->GetOutput();
  check(htg->GetCellData()->GetArray("SignedDistance") == nullptr, "no SignedDistance: the solver is not built");

  std::unique_ptr<sltk::Communicator> comm;
  check(sltk::vtkbridge::makeCommunicator(nullptr, comm).isOk(), "communicator");
  sltk::octree::CloudForestOptions options;
  options.MinimumLevel = 1;
  options.MaximumLevel = 4;
  std::unique_ptr<sltk::octree::CloudForest> forest;
  check(sltk::octree::CloudForest::build(*comm, mine, options, {}, forest).isOk(), "the reference forest");
  const double scale = forest->unitBox().Scale;

  int masked = 0;
  std::vector<HtgLeaf> leaves = unmaskedLeaves(htg, masked);
  check(leaves.size() == forest->leaves().size(),
    "unmasked HTG leaves (" + std::to_string(leaves.size()) + ") are this rank's forest leaves (" +
      std::to_string(forest->leaves().size()) + ")");
  check((size > 1) == (masked > 0), "other ranks' leaves are masked, and only under MPI");
  const std::int64_t total = comm->allReduce(static_cast<std::int64_t>(leaves.size()), sltk::ReduceOp::Sum);
  check(total == forest->stats().GlobalLeaves, "the ranks' unmasked leaves add up to the forest");
  check(htg->GetFieldData()->GetArray("GlobalLeaves")->GetTuple1(0) == static_cast<double>(total),
    "GlobalLeaves in field data");
  std::vector<std::pair<int, double>> fromHtg, fromForest;
  double worst = 0.0;
  for (const HtgLeaf& leaf : leaves)
  {
    double exact = std::numeric_limits<double>::infinity();
    for (const auto& p : cloud.Points)
    {
      exact = std::min(exact, std::hypot(p[0] - leaf.Centre[0], p[1] - leaf.Centre[1], p[2] - leaf.Centre[2]));
    }
    worst = std::max(worst, std::abs(leaf.Distance - exact));
    check(leaf.Rank == rank, "Rank array is the owner");
    fromHtg.emplace_back(leaf.Level, leaf.Distance);
  }
  check(worst < 1e-12, "HTG leaves at the forest's positions: distance error " + std::to_string(worst * 1e12) + "e-12");
  for (const auto& leaf : forest->leaves())
  {
    fromForest.emplace_back(leaf.Level, scale * leaf.Distance);
  }
  std::sort(fromHtg.begin(), fromHtg.end());
  std::sort(fromForest.begin(), fromForest.end());
  check(fromHtg == fromForest, "the HTG's (level, distance) are the forest's");

  // .htg written and read back (one file per rank). Binary (inline) data:
  // VTK 9.2's appended mode corrupts the header of an HTG with several cell
  // arrays (Documentation/Toolchain.md).
  const std::string file = outDir + "/octree-rank" + std::to_string(rank) + ".htg";
  vtkNew<vtkXMLHyperTreeGridWriter> writer;
  writer->SetDataModeToBinary();
  writer->SetInputData(htg);
  writer->SetFileName(file.c_str());
  check(writer->Write() == 1, "writing " + file);
  vtkNew<vtkXMLHyperTreeGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  auto* back = vtkHyperTreeGrid::SafeDownCast(reader->GetOutputDataObject(0));
  int maskedBack = 0;
  std::vector<HtgLeaf> read = back ? unmaskedLeaves(back, maskedBack) : std::vector<HtgLeaf>{};
  check(read.size() == leaves.size() && maskedBack == masked, "the .htg read back has the same leaves");
  bool same = read.size() == leaves.size();
  for (size_t i = 0; same && i < read.size(); ++i)
  {
    same = read[i].Level == leaves[i].Level && read[i].Distance == leaves[i].Distance;
  }
  check(same, "the .htg read back has the same levels and distances");

  // Bad properties are refused on every rank, not clamped.
  filter->SetMaximumLevel(30);
  check(filter->GetExecutive()->Update() == 0 && filter->GetMaximumLevel() == 30, "MaximumLevel 30 is refused");
  filter->SetMaximumLevel(4);
  filter->SetMinimumLevel(5);
  check(filter->GetExecutive()->Update() == 0, "MinimumLevel > MaximumLevel is refused");

  int anyFailed = 0;
  controller->AllReduce(&sltktest::failures(), &anyFailed, 1, vtkCommunicator::MAX_OP);
  forest.reset();
  comm.reset();
  vtkMultiProcessController::SetGlobalController(nullptr);
  controller->Finalize();
  if (rank == 0)
  {
    std::cout << (anyFailed ? "octree HTG: FAILED" : "octree HTG ok") << " on " << size << " rank(s), " << total
              << " leaves\n";
  }
  return anyFailed ? 1 : 0;
}
