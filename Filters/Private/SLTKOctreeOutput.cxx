// SPDX-License-Identifier: GPL-2.0-or-later
#include "SLTKOctreeOutput.h"

#include "sltk/octree/CloudForest.h"

#include "vtkBitArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHyperTree.h"
#include "vtkHyperTreeGrid.h"
#include "vtkHyperTreeGridNonOrientedCursor.h"
#include "vtkIntArray.h"
#include "vtkNew.h"

#include <cmath>
#include <limits>
#include <vector>

namespace sltk
{
namespace vtkbridge
{

namespace
{
/// Level of every cell and whether it is a leaf, walking one hyper tree.
void walk(vtkHyperTreeGridNonOrientedCursor* cursor, std::vector<int>& level, std::vector<char>& leaf)
{
  const vtkIdType id = cursor->GetGlobalNodeIndex();
  level[static_cast<size_t>(id)] = static_cast<int>(cursor->GetLevel());
  leaf[static_cast<size_t>(id)] = cursor->IsLeaf() ? 1 : 0;
  if (!cursor->IsLeaf())
  {
    for (unsigned char child = 0; child < 8; ++child)
    {
      cursor->ToChild(child);
      walk(cursor, level, leaf);
      cursor->ToParent();
    }
  }
}

/// Values of the cells that are not owned leaves: a refined cell gets the
/// mean of its children's (the thesis's coarsening rule, 5.2.2), a masked
/// leaf its parent's. Returns the cell's value, NaN for a masked leaf.
double fillCoarse(vtkHyperTreeGridNonOrientedCursor* cursor, const std::vector<char>& owned, std::vector<double>& value)
{
  const size_t id = static_cast<size_t>(cursor->GetGlobalNodeIndex());
  if (cursor->IsLeaf())
  {
    return owned[id] ? value[id] : std::numeric_limits<double>::quiet_NaN();
  }
  double sum = 0.0;
  int defined = 0;
  std::vector<size_t> maskedChildren;
  for (unsigned char child = 0; child < 8; ++child)
  {
    cursor->ToChild(child);
    const double v = fillCoarse(cursor, owned, value);
    if (std::isnan(v))
    {
      maskedChildren.push_back(static_cast<size_t>(cursor->GetGlobalNodeIndex()));
    }
    else
    {
      sum += v;
      ++defined;
    }
    cursor->ToParent();
  }
  // A refined cell was created on the way to an owned leaf: some child has a value.
  value[id] = defined ? sum / defined : 0.0;
  for (size_t m : maskedChildren)
  {
    value[m] = value[id];
  }
  return value[id];
}
} // namespace

void forestToHyperTreeGrid(const octree::CloudForest& forest, vtkHyperTreeGrid* output)
{
  output->Initialize();
  const octree::BrickGeometry& brick = forest.brick();
  const UnitBox<3>& box = forest.unitBox();
  output->SetDimensions(brick.Trees[0] + 1, brick.Trees[1] + 1, brick.Trees[2] + 1);
  output->SetBranchFactor(2);
  vtkNew<vtkDoubleArray> coordinates[3];
  for (int a = 0; a < 3; ++a)
  {
    coordinates[a]->SetNumberOfTuples(brick.Trees[a] + 1);
    for (int i = 0; i <= brick.Trees[a]; ++i)
    {
      coordinates[a]->SetValue(i, box.Centre[a] + box.Scale * (brick.Origin[a] + i * brick.TreeEdge));
    }
  }
  output->SetXCoordinates(coordinates[0]);
  output->SetYCoordinates(coordinates[1]);
  output->SetZCoordinates(coordinates[2]);

  // Down from each tree's root to every local leaf, subdividing on the way.
  const std::vector<octree::ForestLeaf>& leaves = forest.leaves();
  std::vector<vtkIdType> leafCell(leaves.size());
  vtkNew<vtkHyperTreeGridNonOrientedCursor> cursor;
  vtkIdType cells = 0;
  std::vector<vtkIdType> treeIndices;
  for (size_t begin = 0; begin < leaves.size();)
  {
    const int tree = leaves[begin].Tree;
    const std::array<int, 3> position = forest.treePosition(tree);
    vtkIdType treeIndex = 0;
    output->GetIndexFromLevelZeroCoordinates(treeIndex, static_cast<unsigned int>(position[0]),
      static_cast<unsigned int>(position[1]), static_cast<unsigned int>(position[2]));
    output->InitializeNonOrientedCursor(cursor, treeIndex, true);
    cursor->SetGlobalIndexStart(cells);
    treeIndices.push_back(treeIndex);
    size_t end = begin;
    for (; end < leaves.size() && leaves[end].Tree == tree; ++end)
    {
      const octree::ForestLeaf& leaf = leaves[end];
      cursor->ToRoot();
      for (int l = 1; l <= leaf.Level; ++l)
      {
        if (cursor->IsLeaf())
        {
          cursor->SubdivideLeaf();
        }
        const int shift = 19 - l; // p4est coordinates: 2^19 per tree edge
        const int child = ((leaf.Coords[0] >> shift) & 1) | (((leaf.Coords[1] >> shift) & 1) << 1) |
          (((leaf.Coords[2] >> shift) & 1) << 2);
        cursor->ToChild(static_cast<unsigned char>(child));
      }
      leafCell[end] = cursor->GetGlobalNodeIndex();
    }
    cells += cursor->GetTree()->GetNumberOfVertices();
    begin = end;
  }

  std::vector<int> level(static_cast<size_t>(cells), 0);
  std::vector<char> isLeaf(static_cast<size_t>(cells), 0);
  for (vtkIdType treeIndex : treeIndices)
  {
    output->InitializeNonOrientedCursor(cursor, treeIndex);
    walk(cursor, level, isLeaf);
  }
  std::vector<double> value(static_cast<size_t>(cells), 0.0);
  std::vector<char> owned(static_cast<size_t>(cells), 0);
  vtkNew<vtkIntArray> ranks;
  ranks->SetName("Rank");
  ranks->SetNumberOfTuples(cells);
  ranks->Fill(-1);
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    value[static_cast<size_t>(leafCell[i])] = box.Scale * leaves[i].Distance;
    ranks->SetValue(leafCell[i], leaves[i].Owner);
    owned[static_cast<size_t>(leafCell[i])] = 1;
  }
  for (vtkIdType treeIndex : treeIndices)
  {
    output->InitializeNonOrientedCursor(cursor, treeIndex);
    fillCoarse(cursor, owned, value);
  }
  // No NaN in the arrays: VTK 9.2's .htg writer (appended mode, its default)
  // writes a corrupt file when an array holds NaN (Documentation/Toolchain.md).
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("DistanceToCloud");
  distance->SetNumberOfTuples(cells);
  vtkNew<vtkIntArray> levels;
  levels->SetName("Level");
  levels->SetNumberOfTuples(cells);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    distance->SetValue(c, value[static_cast<size_t>(c)]);
    levels->SetValue(c, level[static_cast<size_t>(c)]);
  }
  output->GetCellData()->AddArray(distance);
  output->GetCellData()->AddArray(levels);
  output->GetCellData()->AddArray(ranks);
  output->GetCellData()->SetActiveScalars("DistanceToCloud");

  bool anyMasked = false;
  vtkNew<vtkBitArray> mask;
  mask->SetName("Mask");
  mask->SetNumberOfTuples(cells);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const bool masked = isLeaf[static_cast<size_t>(c)] && !owned[static_cast<size_t>(c)];
    mask->SetValue(c, masked ? 1 : 0);
    anyMasked = anyMasked || masked;
  }
  if (anyMasked)
  {
    output->SetMask(mask);
  }
}

} // namespace vtkbridge
} // namespace sltk
