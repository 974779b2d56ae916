// SPDX-License-Identifier: BSD-3-Clause
#include "SLTKTiledSurface.h"

#include "SLTKMergePoints.h"

#include "sltk/octree/TiledReconstruction.h"

#include <vtkAppendPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkFlyingEdges2D.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkPolyDataNormals.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <vector>

namespace sltk
{
namespace vtkbridge
{

namespace
{
/// The front of one block's image: vtkFlyingEdges3D's triangles, or in 2D vtkFlyingEdges2D's segments.
vtkSmartPointer<vtkPolyData> contourOf(vtkImageData* image, bool planar)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> contour;
  if (planar)
  {
    auto edges = vtkSmartPointer<vtkFlyingEdges2D>::New();
    edges->SetValue(0, 0.0);
    edges->ComputeScalarsOff();
    contour = edges;
  }
  else
  {
    auto edges = vtkSmartPointer<vtkFlyingEdges3D>::New();
    edges->SetValue(0, 0.0);
    edges->ComputeNormalsOff();
    edges->ComputeGradientsOff();
    edges->ComputeScalarsOff();
    contour = edges;
  }
  contour->SetInputData(image);
  contour->Update();
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  piece->ShallowCopy(contour->GetOutput());
  return piece;
}

/// The front in the cells of the block of tiles from `first` (lower corner in
/// the block): its image over the block's nodes and the next block's first
/// ones, contoured; null when no cell of the block meets the front.
template <int D>
vtkSmartPointer<vtkPolyData> blockFront(
  const TiledField<D>& field, const GridSpec<D>& grid, const std::array<Index, D>& first, double z, GridField<D>& block)
{
  int extent[6] = { 0, 0, 0, 0, 0, 0 }; // a 2D block lies in the plane z
  for (int a = 0; a < D; ++a)
  {
    const Index start = first[a] * TileEdge;
    extent[2 * a] = static_cast<int>(start);
    extent[2 * a + 1] = static_cast<int>(std::min(start + TileBlockEdge * TileEdge, grid.Dims[a] - 1));
  }
  field.scratchBlock(first, TileBlockEdge, 1, 0, block, nullptr);
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
        std::array<Index, D> node{};
        node[0] = i - extent[0] + 1;
        node[1] = j - extent[2] + 1;
        node[D - 1] = D == 3 ? k - extent[4] + 1 : node[D - 1];
        const double v = block(node);
        negative = negative || v < 0.0;
        positive = positive || v >= 0.0;
        values->SetValue(n++, v);
      }
    }
  }
  if (!(negative && positive))
  {
    return nullptr; // no front in this block's cells
  }
  vtkNew<vtkImageData> image;
  image->SetExtent(extent);
  image->SetOrigin(grid.Origin[0], grid.Origin[1], D == 3 ? grid.Origin[D - 1] : z);
  image->SetSpacing(grid.Spacing[0], grid.Spacing[1], D == 3 ? grid.Spacing[D - 1] : 1.0);
  image->GetPointData()->SetScalars(values);
  return contourOf(image, D == 2);
}
} // namespace

template <int D>
void tiledZeroLevelSet(const TiledField<D>& field, const UnitBox<D>& box, vtkPolyData* surface, const Context& ctx,
  const std::vector<std::int32_t>& owners, int rank, double z)
{
  const GridSpec<D> grid = box.toUser(field.grid());
  // The tiles' cells (lower corner in a tile) are contoured by blocks of
  // TileBlockEdge^D tile positions, one image each (a pipeline per tile cost more
  // than the contour). Each image's extent is its block's within the global grid,
  // so a node shared by two blocks has bitwise the same coordinates in both.
  std::vector<std::array<Index, D>> blocks;
  for (std::int32_t id = 0; id < static_cast<std::int32_t>(field.tileCount()); ++id)
  {
    if (!ownedBy(owners, field.tileSlot(id), rank))
    {
      continue; // a ghost: its owner contours it (a block has one owner, TiledReconstruction.h)
    }
    std::array<Index, D> first = field.tileOrigin(id);
    for (Index& t : first)
    {
      t -= t % TileBlockEdge; // the blocks a distributed band gives one owner
    }
    blocks.push_back(first);
  }
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
  // The blocks on the solver's threads (each its own copy and pipeline),
  // appended in block order: the same surface on any thread count.
  // (vtkSMPTools::For over the blocks kept 25 MB more of the bunny's process
  // at its peak: its threads' heaps.)
  std::vector<vtkSmartPointer<vtkPolyData>> pieces(blocks.size());
  ctx.parallelFor(
    0, static_cast<Index>(blocks.size()),
    [&](Index begin, Index end)
    {
      GridField<D> block; // the block and one node around it (TiledField::scratchBlock)
      for (Index b = begin; b < end; ++b)
      {
        pieces[static_cast<size_t>(b)] = blockFront<D>(field, grid, blocks[static_cast<size_t>(b)], z, block);
      }
    },
    4);
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : pieces)
  {
    if (piece)
    {
      append->AddInputData(piece);
    }
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    surface->Initialize();
    return;
  }
  // Points shared by neighbouring blocks are bitwise equal: one point each, numbered by first use
  // (SLTKMergePoints.h: vtkCleanPolyData's result from a hash, as the uniform grid's surface).
  append->Update();
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  mergeCoincidentPoints(append->GetOutput(), merged);
  if (D == 2)
  {
    surface->ShallowCopy(merged); // a curve: no normals (as the uniform grid's, zeroLevelSet)
    return;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(merged);
  normals->SplittingOff();
  // Flying edges orients every triangle by the signs of its cube (outward, to
  // phi > 0), so the triangles are consistent already; the consistency pass
  // (half the normals' time on the bunny) changed no byte of the bunny's
  // surface and could only flip triangles around a non-manifold edge.
  normals->ConsistencyOff();
  // One thread: VTK's threaded normals change the last bits of some normals from run to run
  // (404 of the kitten's 133,396), and the same cloud must give the same file.
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 1 }, [&]() { normals->Update(); });
  surface->ShallowCopy(normals->GetOutput());
}

template void tiledZeroLevelSet(
  const TiledField<2>&, const UnitBox<2>&, vtkPolyData*, const Context&, const std::vector<std::int32_t>&, int, double);
template void tiledZeroLevelSet(
  const TiledField<3>&, const UnitBox<3>&, vtkPolyData*, const Context&, const std::vector<std::int32_t>&, int, double);

} // namespace vtkbridge
} // namespace sltk
