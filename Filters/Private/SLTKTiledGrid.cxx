// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKTiledGrid.h"

#include "vtkBitArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHyperTree.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedCursor.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

namespace sltk
{
namespace vtkbridge
{

namespace
{
/// Values of the cells of one tiled slot, by global cell index.
struct TreeValues
{
  const TiledField<3>& Field;
  std::int32_t Tile;
  double Scale;
  std::vector<double>& Phi;
  std::vector<double>& Distance;
  std::vector<unsigned char>& Level;
  std::vector<unsigned char>& Masked;

  void set(vtkIdType id, double phi, double distance, int level, bool masked)
  {
    const size_t i = static_cast<size_t>(id);
    if (this->Phi.size() <= i)
    {
      const size_t size = std::max(i + 1, 2 * this->Phi.size());
      this->Phi.resize(size);
      this->Distance.resize(size);
      this->Level.resize(size);
      this->Masked.resize(size);
    }
    this->Phi[i] = phi;
    this->Distance[i] = distance;
    this->Level[i] = static_cast<unsigned char>(level);
    this->Masked[i] = masked ? 1 : 0;
  }

  /// The cell at `cursor` covering `size` nodes per axis from tile node
  /// `first` (local coordinates): a leaf per node, refined above. Returns
  /// whether it holds a value (not masked), with its values.
  bool build(vtkHyperTreeGridNonOrientedCursor* cursor, const std::array<Index, 3>& first, Index size, int level,
    double& phi, double& distance)
  {
    const std::array<Index, 3>& origin = this->Field.tileOrigin(this->Tile);
    bool beyond = false; // the whole cell beyond the grid's last node
    for (int a = 0; a < 3; ++a)
    {
      beyond = beyond || origin[a] * TileEdge + first[a] >= this->Field.grid().Dims[a];
    }
    const vtkIdType id = cursor->GetGlobalNodeIndex();
    if (beyond)
    {
      this->set(id, 0.0, 0.0, level, true);
      return false;
    }
    if (size == 1)
    {
      const Index local = first[0] | (first[1] << TileBits) | (first[2] << (2 * TileBits));
      phi = this->Scale * this->Field.phi(this->Tile)[local];
      distance = this->Scale * this->Field.distance(this->Tile)[local];
      this->set(id, phi, distance, level, false);
      return true;
    }
    cursor->SubdivideLeaf();
    const Index half = size / 2;
    double phiSum = 0.0, distanceSum = 0.0;
    int defined = 0;
    for (unsigned char child = 0; child < 8; ++child)
    {
      std::array<Index, 3> corner = first;
      for (int a = 0; a < 3; ++a)
      {
        corner[a] += ((child >> a) & 1) ? half : 0; // VTK's child index: x + 2y + 4z
      }
      cursor->ToChild(child);
      double p = 0.0, d = 0.0;
      if (this->build(cursor, corner, half, level + 1, p, d))
      {
        phiSum += p;
        distanceSum += d;
        ++defined;
      }
      cursor->ToParent();
    }
    phi = phiSum / defined; // the cell's first node lies in the grid: one child at least
    distance = distanceSum / defined;
    this->set(id, phi, distance, level, false);
    return true;
  }
};
} // namespace

void tiledToHyperTreeGrid(const TiledField<3>& field, const UnitBox<3>& box,
  const std::function<double(const std::array<double, 3>&)>& distanceAt, vtkHyperTreeGrid* output)
{
  output->Initialize();
  const std::array<Index, 3>& slots = field.slotDims();
  output->SetDimensions(static_cast<unsigned int>(slots[0] + 1), static_cast<unsigned int>(slots[1] + 1),
    static_cast<unsigned int>(slots[2] + 1));
  output->SetBranchFactor(2);
  const GridSpec<3>& grid = field.grid();
  vtkNew<vtkDoubleArray> coordinates[3];
  for (int a = 0; a < 3; ++a)
  {
    // Dual cells: a tree's first leaf is centred on its slot's first node.
    coordinates[a]->SetNumberOfTuples(slots[a] + 1);
    for (Index i = 0; i <= slots[a]; ++i)
    {
      const double unit = grid.Origin[a] + (static_cast<double>(i * TileEdge) - 0.5) * grid.Spacing[a];
      coordinates[a]->SetValue(i, box.Centre[a] + box.Scale * unit);
    }
  }
  output->SetXCoordinates(coordinates[0]);
  output->SetYCoordinates(coordinates[1]);
  output->SetZCoordinates(coordinates[2]);

  std::vector<double> phi, distance;
  std::vector<unsigned char> level, masked;
  vtkNew<vtkHyperTreeGridNonOrientedCursor> cursor;
  vtkIdType cells = 0;
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    const std::array<Index, 3> t = field.slotCoordinates(s);
    vtkIdType treeIndex = 0;
    output->GetIndexFromLevelZeroCoordinates(
      treeIndex, static_cast<unsigned int>(t[0]), static_cast<unsigned int>(t[1]), static_cast<unsigned int>(t[2]));
    output->InitializeNonOrientedCursor(cursor, treeIndex, true);
    cursor->SetGlobalIndexStart(cells);
    const std::int32_t entry = field.slot(s);
    TreeValues values{ field, entry, box.Scale, phi, distance, level, masked };
    if (entry >= 0)
    {
      double p = 0.0, d = 0.0;
      values.build(cursor, { 0, 0, 0 }, TileEdge, 0, p, d);
    }
    else
    {
      std::array<double, 3> centre{};
      for (int a = 0; a < 3; ++a)
      {
        centre[a] = grid.Origin[a] + (static_cast<double>(t[a] * TileEdge) + 0.5 * (TileEdge - 1)) * grid.Spacing[a];
      }
      const double side = entry == TiledField<3>::Inside ? -field.gamma() : field.gamma();
      values.set(cursor->GetGlobalNodeIndex(), box.Scale * side, box.Scale * distanceAt(centre), 0, false);
    }
    cells += static_cast<vtkIdType>(cursor->GetTree()->GetNumberOfVertices());
  }

  vtkNew<vtkDoubleArray> phiArray, distanceArray;
  phiArray->SetName("SignedDistance");
  distanceArray->SetName("DistanceToCloud");
  vtkNew<vtkUnsignedCharArray> levelArray;
  levelArray->SetName("Level");
  vtkNew<vtkBitArray> mask;
  mask->SetName("Mask");
  phiArray->SetNumberOfTuples(cells);
  distanceArray->SetNumberOfTuples(cells);
  levelArray->SetNumberOfTuples(cells);
  mask->SetNumberOfTuples(cells);
  bool anyMasked = false;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const size_t i = static_cast<size_t>(c);
    phiArray->SetValue(c, phi[i]);
    distanceArray->SetValue(c, distance[i]);
    levelArray->SetValue(c, level[i]);
    mask->SetValue(c, masked[i]);
    anyMasked = anyMasked || masked[i];
  }
  output->GetCellData()->AddArray(phiArray);
  output->GetCellData()->AddArray(distanceArray);
  output->GetCellData()->AddArray(levelArray);
  output->GetCellData()->SetActiveScalars("SignedDistance");
  if (anyMasked)
  {
    output->SetMask(mask);
  }
}

} // namespace vtkbridge
} // namespace sltk
