// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKTiledGrid.h"

#include "sltk/octree/TiledReconstruction.h"

#include "vtkBitArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHyperTree.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedCursor.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"

#include <stdexcept>
#include <string>

namespace sltk
{
namespace vtkbridge
{

namespace
{
/// The corner of child `child` (VTK's index x + 2y (+ 4z)) of a cell at `first` of `half` nodes per axis.
template <int D>
std::array<Index, D> childCorner(const std::array<Index, D>& first, Index half, unsigned char child)
{
  std::array<Index, D> corner = first;
  for (int a = 0; a < D; ++a)
  {
    corner[a] += ((child >> a) & 1) ? half : 0;
  }
  return corner;
}

/// Cells of a tile's tree below (and with) the cell at `first` covering `size` nodes per axis.
template <int D>
vtkIdType countCells(const TiledField<D>& field, std::int32_t tile, const std::array<Index, D>& first, Index size)
{
  if (size == 1 || !field.nodeInGrid(tile, first) || field.flatCell(tile, first, size))
  {
    return 1;
  }
  vtkIdType cells = 1;
  for (unsigned char child = 0; child < (1 << D); ++child)
  {
    cells += countCells<D>(field, tile, childCorner<D>(first, size / 2, child), size / 2);
  }
  return cells;
}

/// The cell data arrays, written by global cell index.
struct CellValues
{
  double* Phi;
  double* Distance;
  unsigned char* Level;
  vtkBitArray* Mask;

  void set(vtkIdType id, double phi, double distance, int level, bool masked)
  {
    this->Phi[id] = phi;
    this->Distance[id] = distance;
    this->Level[id] = static_cast<unsigned char>(level);
    this->Mask->SetValue(id, masked ? 1 : 0);
  }
};

/// The unit-box centre of the cell covering `size` nodes per axis from node
/// `first` of the slot at tile coordinates `t`: the mean of its nodes.
template <int D>
std::array<double, D> cellCentre(
  const TiledField<D>& field, const std::array<Index, D>& t, const std::array<Index, D>& first, Index size)
{
  std::array<double, D> centre{};
  for (int a = 0; a < D; ++a)
  {
    centre[a] = field.grid().Origin[a] +
      (static_cast<double>(t[a] * TileEdge + first[a]) + 0.5 * static_cast<double>(size - 1)) * field.grid().Spacing[a];
  }
  return centre;
}

template <int D>
using DistanceAt = std::function<double(const std::array<double, D>&)>;

/// The tile-local index of the node `first` (x fastest).
template <int D>
Index localIndex(const std::array<Index, D>& first)
{
  Index local = 0;
  for (int a = 0; a < D; ++a)
  {
    local |= first[a] << (TileBits * a);
  }
  return local;
}

/// Builds the cell at `cursor` of tile `tile` covering `size` nodes per axis
/// from its node `first`: a leaf per node, or one for a flat cell
/// (TiledField::flatCell: its +-gamma, the distance at its centre), refined
/// above, masked beyond the grid. Returns whether it holds a value (not
/// masked), with its values.
template <int D>
bool build(const TiledField<D>& field, std::int32_t tile, double scale, const DistanceAt<D>& distanceAt,
  vtkHyperTreeGridNonOrientedCursor* cursor, const std::array<Index, D>& first, Index size, int level, CellValues& out,
  double& phi, double& distance)
{
  const vtkIdType id = cursor->GetGlobalNodeIndex();
  if (!field.nodeInGrid(tile, first))
  {
    out.set(id, 0.0, 0.0, level, true);
    return false;
  }
  if (size > 1 && field.flatCell(tile, first, size))
  {
    phi = scale * field.phi(tile)[localIndex<D>(first)];
    distance = scale * distanceAt(cellCentre<D>(field, field.tileOrigin(tile), first, size));
    out.set(id, phi, distance, level, false);
    return true;
  }
  if (size == 1)
  {
    const Index local = localIndex<D>(first);
    phi = scale * field.phi(tile)[local];
    distance = scale * field.distance(tile)[local];
    out.set(id, phi, distance, level, false);
    return true;
  }
  cursor->SubdivideLeaf();
  double phiSum = 0.0, distanceSum = 0.0;
  int defined = 0;
  for (unsigned char child = 0; child < (1 << D); ++child)
  {
    cursor->ToChild(child);
    double p = 0.0, d = 0.0;
    if (build<D>(field, tile, scale, distanceAt, cursor, childCorner<D>(first, size / 2, child), size / 2, level + 1,
          out, p, d))
    {
      phiSum += p;
      distanceSum += d;
      ++defined;
    }
    cursor->ToParent();
  }
  phi = phiSum / defined; // the cell's first node lies in the grid: one child at least
  distance = distanceSum / defined;
  out.set(id, phi, distance, level, false);
  return true;
}
} // namespace

template <int D>
void tiledToHyperTreeGrid(const TiledField<D>& field, const UnitBox<D>& box,
  const std::function<double(const std::array<double, D>&)>& distanceAt, vtkHyperTreeGrid* output, const Context& ctx,
  const std::vector<std::int32_t>& owners, int rank, double z)
{
  const auto mine = [&](Index s) { return ownedBy(owners, s, rank); };
  output->Initialize();
  std::array<Index, 3> slots{ 0, 0, 0 }; // a planar grid: one tree along z (a quadtree per slot)
  for (int a = 0; a < D; ++a)
  {
    slots[a] = field.slotDims()[a];
  }
  output->SetDimensions(static_cast<unsigned int>(slots[0] + 1), static_cast<unsigned int>(slots[1] + 1),
    static_cast<unsigned int>(slots[2] + 1));
  output->SetBranchFactor(2);
  // A planar grid's trees in transposed order (y fastest): ParaView 5.11's
  // vtkHyperTreeGridGhostCellsGenerator finds a 2D tree's neighbours in that
  // order only (VTK fixed it later, 4ea563a3a2); without it the ghost exchange
  // under MPI aborts (MPI_ERR_TRUNCATE) or closes the contour wrongly.
  output->SetTransposedRootIndexing(D == 2);
  const GridSpec<D>& grid = field.grid();
  vtkNew<vtkDoubleArray> coordinates[3];
  coordinates[2]->InsertNextValue(z); // replaced in 3D
  for (int a = 0; a < D; ++a)
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

  // The cells first (a tile's tree: its nodes in the grid and the cells above them), then the arrays.
  vtkIdType cells = 0;
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    const std::int32_t entry = field.slot(s);
    cells += !mine(s) ? 0 : (entry >= 0 ? countCells<D>(field, entry, std::array<Index, D>{}, TileEdge) : 1);
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
  CellValues out{ phiArray->GetPointer(0), distanceArray->GetPointer(0), levelArray->GetPointer(0), mask };

  // The distance at the centre of every slot without a tile, on ctx's threads
  // first: one query each, most of them far from the cloud.
  std::vector<double> slotDistance(static_cast<size_t>(field.slotCount()), 0.0);
  ctx.parallelFor(
    0, field.slotCount(),
    [&](Index b, Index e)
    {
      for (Index s = b; s < e; ++s)
      {
        if (mine(s) && field.slot(s) < 0)
        {
          slotDistance[static_cast<size_t>(s)] =
            distanceAt(cellCentre<D>(field, field.slotCoordinates(s), std::array<Index, D>{}, TileEdge));
        }
      }
    },
    64);
  vtkNew<vtkHyperTreeGridNonOrientedCursor> cursor;
  vtkIdType start = 0;
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    if (!mine(s))
    {
      continue; // another rank's tree
    }
    const std::array<Index, D> t = field.slotCoordinates(s);
    vtkIdType treeIndex = 0;
    output->GetIndexFromLevelZeroCoordinates(treeIndex, static_cast<unsigned int>(t[0]),
      static_cast<unsigned int>(t[1]), D == 3 ? static_cast<unsigned int>(t[D - 1]) : 0u);
    output->InitializeNonOrientedCursor(cursor, treeIndex, true);
    cursor->SetGlobalIndexStart(start);
    const std::int32_t entry = field.slot(s);
    if (entry >= 0)
    {
      double p = 0.0, d = 0.0;
      build<D>(field, entry, box.Scale, distanceAt, cursor, std::array<Index, D>{}, TileEdge, 0, out, p, d);
    }
    else
    {
      const double side = entry == TiledField<D>::Inside ? -field.gamma() : field.gamma();
      out.set(
        cursor->GetGlobalNodeIndex(), box.Scale * side, box.Scale * slotDistance[static_cast<size_t>(s)], 0, false);
    }
    start += static_cast<vtkIdType>(cursor->GetTree()->GetNumberOfVertices());
  }
  if (start != cells)
  {
    throw std::logic_error("tiledToHyperTreeGrid: the trees have " + std::to_string(start) + " cells, not the " +
      std::to_string(cells) + " counted");
  }
  vtkNew<vtkIntArray> rankArray; // the owning rank (vtkOctreeSDF's array of the same name)
  rankArray->SetName("Rank");
  rankArray->SetNumberOfTuples(cells);
  rankArray->FillValue(rank);
  output->GetCellData()->AddArray(phiArray);
  output->GetCellData()->AddArray(distanceArray);
  output->GetCellData()->AddArray(levelArray);
  output->GetCellData()->AddArray(rankArray);
  output->GetCellData()->SetActiveScalars("SignedDistance");
  // Always a mask, even with nothing masked: the ghost cells generator sizes
  // its messages by whether the receiving rank has one (ParaView 5.11).
  output->SetMask(mask);
}

template void tiledToHyperTreeGrid<2>(const TiledField<2>&, const UnitBox<2>&,
  const std::function<double(const std::array<double, 2>&)>&, vtkHyperTreeGrid*, const Context&,
  const std::vector<std::int32_t>&, int, double);
template void tiledToHyperTreeGrid<3>(const TiledField<3>&, const UnitBox<3>&,
  const std::function<double(const std::array<double, 3>&)>&, vtkHyperTreeGrid*, const Context&,
  const std::vector<std::int32_t>&, int, double);

} // namespace vtkbridge
} // namespace sltk
