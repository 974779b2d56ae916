// SPDX-License-Identifier: BSD-3-Clause
// vtkOctreeSDF, the octree reconstruction, serially and under `mpiexec -n 2`,
// on a sphere of points (every rank reads the whole cloud, as from a file):
// - port 0 is a hyper tree grid whose unmasked leaves are this rank's (Rank),
//   at the finest level the signed distance of the sphere within a fraction
//   of a cell and the exact distance to the cloud at the leaf's centre (the
//   leaves sit at the nodes); the ranks' leaves add up to GlobalLeaves and
//   to the history's Leaves;
// - on 2 ranks, every leaf's signed distance is the one-rank filter's at the
//   same leaf (each rank also runs it alone, vtkDummyController) and the
//   leaf count is the same; with the points on rank 0 only (the others have
//   none) the union of the pieces gives the same leaves bit for bit, and
//   every rank's surface piece the cloud's point array (Height); pieces that
//   disagree on an array lose it with a warning;
// - port 1, gathered, is one closed surface; port 2 holds the leaves per
//   iteration;
// - the .htg written and read back holds the same leaves;
// Usage: sltkFiltersOctreeTests OUTPUT_DIR
#include "FilterTestCheck.h"
#include "OctreeLeaves.h"
#include "SLTKBridge.h"

#include "sltk/cloud/SyntheticClouds.h"
#include "vtkOctreeSDF.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedGeometryCursor.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkXMLHyperTreeGridReader.h"
#include "vtkXMLHyperTreeGridWriter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
using sltktest::check;
using sltktest::fieldValue;
using sltktest::Leaf;
using sltktest::leavesOf;

double lastColumnValue(vtkTable* table, const char* column)
{
  auto* a = table ? vtkDataArray::SafeDownCast(table->GetColumnByName(column)) : nullptr;
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(a->GetNumberOfTuples() - 1) : std::nan("");
}

/// Counts the warnings of the object it observes.
class WarningCounter : public vtkCommand
{
public:
  static WarningCounter* New() { return new WarningCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  int Count = 0;
};

/// Boundary and non-manifold edges of the cleaned union of `pieces`.
vtkIdType openEdges(const std::vector<vtkSmartPointer<vtkDataObject>>& pieces, vtkIdType& polys)
{
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : pieces)
  {
    append->AddInputData(vtkPolyData::SafeDownCast(piece));
  }
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(append->GetOutputPort());
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputConnection(merged->GetOutputPort());
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  polys = merged->GetOutput()->GetNumberOfPolys();
  return edges->GetOutput()->GetNumberOfCells();
}
} // namespace

int main(int argc, char* argv[])
{
  const auto [controller, rank, size] = sltktest::startMpi(&argc, &argv);
  const std::string outDir = argc > 1 ? argv[1] : ".";

  const std::array<double, 3> centre{ 2.0, 1.0, -1.0 };
  const double radius = 1.0;
  const sltk::PointCloud<3> cloud = sltk::sphereCloud(2000, radius, centre);
  vtkSmartPointer<vtkPolyData> input = sltk::vtkbridge::pointsOf(cloud);
  vtkNew<vtkDoubleArray> height; // a scan's attribute: the surface's vertices take their nearest point's
  height->SetName("Height");
  height->SetNumberOfTuples(static_cast<vtkIdType>(cloud.Points.size()));
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(cloud.Points.size()); ++i)
  {
    height->SetValue(i, cloud.Points[static_cast<size_t>(i)][2]);
  }
  input->GetPointData()->AddArray(height);

  vtkNew<vtkOctreeSDF> filter;
  filter->SetInputDataObject(input);
  filter->SetNumberOfRuns(2);
  filter->SetNumberOfThreads(1);
  check(filter->GetExecutive()->Update() == 1, "the sphere is reconstructed");
  vtkHyperTreeGrid* htg = filter->GetOutput();
  const std::vector<Leaf> leaves = leavesOf(htg);
  check(!leaves.empty(), "port 0 is a hyper tree grid with SignedDistance, DistanceToCloud, Level and Rank");

  // Every unmasked leaf is this rank's; at the finest level (a stored node) the signed
  // distance is the sphere's within a fraction of a cell near the front.
  // Every leaf, coarse (a flat cell, a slot without a tile) or not, holds the exact distance
  // at its centre; a coarse one holds +-gamma, beyond the finest leaves' values.
  double worstPhi = 0.0, worstDistance = 0.0, cell = 0.0, gamma = 0.0, largestFine = 0.0;
  bool coarseAtGamma = true;
  for (const Leaf& leaf : leaves)
  {
    double exact = std::numeric_limits<double>::infinity();
    for (const auto& p : cloud.Points)
    {
      exact = std::min(exact, std::hypot(p[0] - leaf.Centre[0], p[1] - leaf.Centre[1], p[2] - leaf.Centre[2]));
    }
    worstDistance = std::max(worstDistance, std::abs(leaf.Distance - exact));
    if (leaf.Level != 3)
    {
      coarseAtGamma = coarseAtGamma && (gamma == 0.0 || std::abs(leaf.Phi) == gamma);
      gamma = std::abs(leaf.Phi);
      continue;
    }
    cell = leaf.Size;
    largestFine = std::max(largestFine, std::abs(leaf.Phi));
    const double r = std::hypot(leaf.Centre[0] - centre[0], leaf.Centre[1] - centre[1], leaf.Centre[2] - centre[2]);
    if (std::abs(leaf.Phi) < 2.0 * leaf.Size)
    {
      worstPhi = std::max(worstPhi, std::abs(leaf.Phi - (r - radius)) / leaf.Size);
    }
  }
  // Under half a cell with WENO3; the automatic interpolator takes the least-squares Q1 on
  // this clean cloud, whose surface lies up to 0.57 cells from the sphere here (1.04-1.11x
  // WENO3's Chamfer distance on smooth spheres, Documentation/Profile.md).
  check(cell > 0.0 && worstPhi < 0.6,
    "SignedDistance is the sphere's within " + std::to_string(worstPhi) + " cells near the front");
  check(worstDistance < 1e-12,
    "DistanceToCloud is exact at every leaf's centre (" + std::to_string(worstDistance * 1e12) + "e-12)");
  check(coarseAtGamma && gamma > 2.0 * cell && largestFine <= gamma,
    "the coarse leaves hold +-gamma (" + std::to_string(gamma / cell) + " cells), the finest at most that");

  // The ranks' leaves add up to GlobalLeaves and to the history's last Leaves (rank 0's table).
  long long total = 0, mine = static_cast<long long>(leaves.size()), largest = 0, fewest = 0;
  controller->AllReduce(&mine, &total, 1, vtkCommunicator::SUM_OP);
  controller->AllReduce(&mine, &largest, 1, vtkCommunicator::MAX_OP);
  controller->AllReduce(&mine, &fewest, 1, vtkCommunicator::MIN_OP);
  check(fewest > 0 && htg->GetCellData()->GetArray("Rank")->GetRange()[0] == rank &&
      htg->GetCellData()->GetArray("Rank")->GetRange()[1] == rank,
    "every rank outputs leaves, all with its Rank");
  check(fieldValue(htg, "GlobalLeaves") == static_cast<double>(total),
    "GlobalLeaves (" + std::to_string(fieldValue(htg, "GlobalLeaves")) + ") is the ranks' leaves (" +
      std::to_string(total) + ")");
  auto* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(2));
  if (rank == 0)
  {
    // The last row is the last iteration's; the run stops at the next one, after its band moved.
    const double lastLeaves = lastColumnValue(table, "Leaves"),
                 lastLargest = lastColumnValue(table, "LargestRankLeaves");
    check(std::abs(lastLeaves - static_cast<double>(total)) < 0.02 * static_cast<double>(total) &&
        lastLargest <= lastLeaves && lastLargest * size >= lastLeaves && (size > 1 || lastLargest == lastLeaves),
      "the history's last Leaves (" + std::to_string(lastLeaves) + ") and LargestRankLeaves (" +
        std::to_string(lastLargest) + ") against the leaves output (" + std::to_string(total) +
        ", the most on a rank " + std::to_string(largest) + ")");
    check(lastColumnValue(table, "UniformNodes") == fieldValue(htg, "RunUniformNodes", 1) &&
        lastColumnValue(table, "StoredNodes") < lastColumnValue(table, "UniformNodes"),
      "the history's UniformNodes is run 2's grid, which stores fewer nodes");
    check(fieldValue(htg, "RunLeaves", 1) == static_cast<double>(total) &&
        fieldValue(htg, "RunLargestRankLeaves", 1) == static_cast<double>(largest) &&
        fieldValue(htg, "RunLeaves", 0) == fieldValue(htg, "RunUniformNodes", 0),
      "RunLeaves and RunLargestRankLeaves of run 2 are the leaves output and the most on a rank (" +
        std::to_string(largest) + "); run 1's leaves are its uniform grid's nodes");
  }

  // The surface pieces join into one closed surface.
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->Gather(filter->GetOutputDataObject(1), pieces, 0);
  if (rank == 0)
  {
    vtkIdType polys = 0;
    const vtkIdType open = openEdges(pieces, polys);
    check(polys > 1000 && open == 0,
      "the surface pieces join into a closed surface (" + std::to_string(polys) + " triangles)");
  }

  // On several ranks: the one-rank filter's leaves and values, leaf by leaf.
  double worstAgainstOneRank = 0.0;
  if (size > 1)
  {
    vtkNew<vtkOctreeSDF> serial;
    serial->SetNumberOfRuns(2);
    check(sltktest::updateAlone(serial, input), "the one-rank reference");
    const std::vector<Leaf> reference = leavesOf(serial->GetOutput());
    const sltktest::LeafAgreement agreed = sltktest::agreement(leaves, reference, cell);
    const long long missing = agreed.Missing;
    const double worst = agreed.WorstInCells;
    check(static_cast<long long>(reference.size()) == total && missing == 0,
      "the ranks' leaves are the one-rank leaves (" + std::to_string(total) + ", " + std::to_string(missing) +
        " not found)");
    check(worst < 1e-10, "SignedDistance within 1e-10 cell of one rank's (" + std::to_string(worst * 1e15) + "e-15)");
    controller->AllReduce(&worst, &worstAgainstOneRank, 1, vtkCommunicator::MAX_OP);

    // The cloud on rank 0 only (the others have no points): the union of the pieces is the
    // whole cloud in its order, so every leaf is the whole-cloud run's, bit for bit.
    vtkNew<vtkOctreeSDF> pieces;
    pieces->SetInputDataObject(rank == 0 ? input : sltk::vtkbridge::pointsOf({}));
    pieces->SetNumberOfRuns(2);
    pieces->SetNumberOfThreads(1);
    check(pieces->GetExecutive()->Update() == 1, "the cloud on rank 0 only is reconstructed");
    const std::vector<Leaf> fromPieces = leavesOf(pieces->GetOutput());
    bool same = fromPieces.size() == leaves.size();
    for (size_t i = 0; same && i < leaves.size(); ++i)
    {
      same = fromPieces[i].Phi == leaves[i].Phi && fromPieces[i].Centre == leaves[i].Centre;
    }
    check(same && fieldValue(pieces->GetOutput(), "GlobalLeaves") == static_cast<double>(total),
      "the cloud on rank 0 only gives the whole-cloud leaves and values, bit for bit");
    // Its surface piece takes the point arrays of rank 0's piece: each vertex's Height is its
    // nearest point's z, within DistanceToCloud of its own. (On 4 ranks a rank may own no
    // block the surface crosses: an empty piece.)
    auto* piece = vtkPolyData::SafeDownCast(pieces->GetOutputDataObject(1));
    const vtkIdType vertices = piece ? piece->GetNumberOfPoints() : 0;
    vtkDataArray* distance = piece ? piece->GetPointData()->GetArray("DistanceToCloud") : nullptr;
    vtkDataArray* heights = piece ? piece->GetPointData()->GetArray("Height") : nullptr;
    bool near = vertices == 0 || (distance && heights);
    for (vtkIdType v = 0; near && v < vertices; ++v)
    {
      near = std::abs(heights->GetTuple1(v) - piece->GetPoint(v)[2]) <= distance->GetTuple1(v) + 1e-12;
    }
    long long withVertices = vertices > 0 ? 1 : 0, ranksWithVertices = 0;
    controller->AllReduce(&withVertices, &ranksWithVertices, 1, vtkCommunicator::SUM_OP);
    check(near && ranksWithVertices >= 2,
      "a rank without points still gives its surface piece DistanceToCloud and the cloud's Height (" +
        std::to_string(ranksWithVertices) + " ranks with vertices)");

    // Pieces that disagree on an array (Height on rank 0's only): it cannot be transferred, and
    // the filter says so with a warning on every rank rather than dropping it silently.
    vtkNew<vtkPolyData> half;
    vtkNew<vtkPoints> halfPoints;
    vtkNew<vtkDoubleArray> halfHeight;
    halfHeight->SetName("Height");
    for (vtkIdType i = rank; i < input->GetNumberOfPoints(); i += size)
    {
      halfPoints->InsertNextPoint(input->GetPoint(i));
      halfHeight->InsertNextValue(input->GetPoint(i)[2]);
    }
    half->SetPoints(halfPoints);
    if (rank == 0)
    {
      half->GetPointData()->AddArray(halfHeight);
    }
    vtkNew<vtkOctreeSDF> disagreeing;
    vtkNew<WarningCounter> warnings;
    disagreeing->AddObserver(vtkCommand::WarningEvent, warnings);
    disagreeing->SetInputDataObject(half);
    disagreeing->SetNumberOfRuns(1);
    disagreeing->SetNumberOfThreads(1);
    check(disagreeing->GetExecutive()->Update() == 1, "pieces with different arrays are reconstructed");
    auto* withoutHeight = vtkPolyData::SafeDownCast(disagreeing->GetOutputDataObject(1));
    check(warnings->Count == 1 && withoutHeight && !withoutHeight->GetPointData()->GetArray("Height"),
      "an array some pieces lack is not transferred, with a warning (" + std::to_string(warnings->Count) + ")");
  }

  // .htg written and read back (one file per rank; binary data: VTK 9.2's appended mode
  // corrupts a hyper tree grid with several cell arrays, Documentation/Toolchain.md).
  const std::string file = outDir + "/octree-sdf-rank" + std::to_string(rank) + ".htg";
  vtkNew<vtkXMLHyperTreeGridWriter> writer;
  writer->SetDataModeToBinary();
  writer->SetInputData(htg);
  writer->SetFileName(file.c_str());
  check(writer->Write() == 1, "writing " + file);
  vtkNew<vtkXMLHyperTreeGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  const std::vector<Leaf> read = leavesOf(vtkHyperTreeGrid::SafeDownCast(reader->GetOutputDataObject(0)));
  bool same = read.size() == leaves.size();
  for (size_t i = 0; same && i < read.size(); ++i)
  {
    same = read[i].Level == leaves[i].Level && read[i].Phi == leaves[i].Phi && read[i].Rank == leaves[i].Rank;
  }
  check(same, "the .htg read back has the same leaves and values");

  int anyFailed = 0;
  controller->AllReduce(&sltktest::failures(), &anyFailed, 1, vtkCommunicator::MAX_OP);
  vtkMultiProcessController::SetGlobalController(nullptr);
  controller->Finalize();
  if (rank == 0)
  {
    std::cout << (anyFailed ? "octree SDF: FAILED" : "octree SDF ok") << " on " << size << " rank(s): " << total
              << " leaves, signed distance within " << worstPhi << " cells of the sphere's and " << worstAgainstOneRank
              << " cells of one rank's\n";
  }
  return anyFailed ? 1 : 0;
}
