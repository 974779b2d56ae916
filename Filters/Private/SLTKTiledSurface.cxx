// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKTiledSurface.h"

#include <vtkAppendPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkStaticCleanPolyData.h>

#include <algorithm>
#include <array>
#include <vector>

namespace sltk
{
namespace vtkbridge
{

void tiledZeroLevelSet(const TiledField<3>& field, const UnitBox<3>& box, vtkPolyData* surface,
  const std::vector<std::int32_t>& owners, int rank)
{
  const GridSpec<3> grid = box.toUser(field.grid());
  // The tiles' cells (lower corner in a tile) are contoured by blocks of
  // BlockTiles^3 tile positions, one image each (a pipeline per tile cost more
  // than the contour). Each image's extent is its block's within the global grid,
  // so a node shared by two blocks has bitwise the same coordinates in both.
  constexpr Index BlockTiles = TileBlockEdge; // the blocks a distributed band gives one owner
  std::vector<std::array<Index, 3>> blocks;
  for (std::int32_t id = 0; id < static_cast<std::int32_t>(field.tileCount()); ++id)
  {
    if (!owners.empty() && owners[static_cast<size_t>(field.tileSlot(id))] != rank)
    {
      continue; // a ghost: its owner contours it (a block has one owner, TiledReconstruction.h)
    }
    std::array<Index, 3> first = field.tileOrigin(id);
    for (Index& t : first)
    {
      t -= t % BlockTiles;
    }
    blocks.push_back(first);
  }
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  vtkNew<vtkAppendPolyData> append;
  GridField<3> block; // the block and one node around it (TiledField::scratchBlock)
  for (const auto& first : blocks)
  {
    int extent[6];
    for (int a = 0; a < 3; ++a)
    {
      const Index start = first[a] * TileEdge;
      extent[2 * a] = static_cast<int>(start);
      extent[2 * a + 1] = static_cast<int>(std::min(start + BlockTiles * TileEdge, grid.Dims[a] - 1));
    }
    field.scratchBlock(first, BlockTiles, 1, 0, block, nullptr);
    bool negative = false, positive = false;
    vtkNew<vtkDoubleArray> values;
    values->SetName("SignedDistance");
    values->SetNumberOfTuples(
      static_cast<vtkIdType>(extent[1] - extent[0] + 1) * (extent[3] - extent[2] + 1) * (extent[5] - extent[4] + 1));
    vtkIdType n = 0;
    for (int k = extent[4]; k <= extent[5]; ++k)
    {
      for (int j = extent[2]; j <= extent[3]; ++j)
      {
        for (int i = extent[0]; i <= extent[1]; ++i)
        {
          const double v = block(std::array<Index, 3>{ i - extent[0] + 1, j - extent[2] + 1, k - extent[4] + 1 });
          negative = negative || v < 0.0;
          positive = positive || v >= 0.0;
          values->SetValue(n++, v);
        }
      }
    }
    if (!(negative && positive))
    {
      continue; // no front in this block's cells
    }
    vtkNew<vtkImageData> image;
    image->SetExtent(extent);
    image->SetOrigin(grid.Origin[0], grid.Origin[1], grid.Origin[2]);
    image->SetSpacing(grid.Spacing[0], grid.Spacing[1], grid.Spacing[2]);
    image->GetPointData()->SetScalars(values);
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputData(image);
    contour->SetValue(0, 0.0);
    contour->ComputeNormalsOff();
    contour->ComputeGradientsOff();
    contour->ComputeScalarsOff();
    contour->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(contour->GetOutput());
    append->AddInputData(piece);
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    surface->Initialize();
    return;
  }
  vtkNew<vtkStaticCleanPolyData> merge; // points shared by neighbouring blocks are bitwise equal
  merge->SetInputConnection(append->GetOutputPort());
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(0.0);
  merge->ConvertLinesToPointsOff();
  merge->ConvertPolysToLinesOff();
  merge->ConvertStripsToPolysOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(merge->GetOutputPort());
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->Update();
  surface->ShallowCopy(normals->GetOutput());
}

} // namespace vtkbridge
} // namespace sltk
