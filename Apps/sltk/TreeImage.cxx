// SPDX-License-Identifier: BSD-3-Clause
#include "TreeImage.h"

#include "WriteAtomically.h"
#include "XmlDataSettings.h"

#include "sltk/octree/TiledField.h"

#include <vtkBitArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkHyperTreeGrid.h>
#include <vtkHyperTreeGridNonOrientedCursor.h>
#include <vtkImageAlgorithm.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>

namespace sltkcli
{

namespace
{
/// The trees' values as image data, any extent on request (CAN_PRODUCE_SUB_EXTENT).
class TreeImageSource : public vtkImageAlgorithm
{
public:
  static TreeImageSource* New();
  vtkTypeMacro(TreeImageSource, vtkImageAlgorithm);

  /// `edge`: the nodes of a tree per axis (its root's cell); `dims`: the grid's nodes.
  void SetTrees(vtkHyperTreeGrid* trees, const std::array<long long, 3>& dims, int edge)
  {
    this->Trees = trees;
    this->Dims = dims;
    this->Edge = edge;
    this->Phi = trees->GetCellData()->GetArray("SignedDistance");
    this->Distance = trees->GetCellData()->GetArray("DistanceToCloud");
    this->Modified();
  }

protected:
  TreeImageSource() { this->SetNumberOfInputPorts(0); }

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override
  {
    vtkInformation* out = outputs->GetInformationObject(0);
    int whole[6] = { 0, 0, 0, 0, 0, 0 };
    double origin[3], spacing[3];
    for (int a = 0; a < 3; ++a)
    {
      vtkDataArray* bounds = this->coordinates(a);
      whole[2 * a + 1] = static_cast<int>(this->Dims[a] - 1);
      // Dual cells: a tree's first leaf is centred on its first node (SLTKTiledGrid.cxx).
      spacing[a] = bounds->GetNumberOfTuples() > 1 ? (bounds->GetTuple1(1) - bounds->GetTuple1(0)) / this->Edge : 1.0;
      origin[a] = bounds->GetNumberOfTuples() > 1 ? bounds->GetTuple1(0) + 0.5 * spacing[a] : bounds->GetTuple1(0);
    }
    for (int a = static_cast<int>(this->Trees->GetDimension()); a < 3; ++a)
    {
      spacing[a] = spacing[0]; // a planar grid's third axis, as the uniform image has it
    }
    out->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole, 6);
    out->Set(vtkDataObject::ORIGIN(), origin, 3);
    out->Set(vtkDataObject::SPACING(), spacing, 3);
    out->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
    vtkDataObject::SetPointDataActiveScalarInfo(out, VTK_DOUBLE, 1);
    return 1;
  }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs) override
  {
    vtkInformation* out = outputs->GetInformationObject(0);
    vtkImageData* image = vtkImageData::GetData(out);
    int extent[6];
    out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    image->SetExtent(extent);
    image->SetOrigin(out->Get(vtkDataObject::ORIGIN()));
    image->SetSpacing(out->Get(vtkDataObject::SPACING()));
    const vtkIdType nodes = image->GetNumberOfPoints();
    vtkNew<vtkDoubleArray> phi, distance;
    phi->SetName("SignedDistance");
    distance->SetName("DistanceToCloud");
    phi->SetNumberOfTuples(nodes);
    distance->SetNumberOfTuples(nodes);
    this->Out = Piece{ extent, phi->GetPointer(0), distance->GetPointer(0), 0 };
    vtkNew<vtkHyperTreeGridNonOrientedCursor> cursor;
    const int dimension = static_cast<int>(this->Trees->GetDimension());
    unsigned int roots[3] = { 1, 1, 1 };
    this->Trees->GetCellDims(roots);
    int first[3], last[3];
    for (int a = 0; a < 3; ++a)
    {
      first[a] = a < dimension ? extent[2 * a] / this->Edge : 0;
      last[a] = a < dimension ? std::min<int>(extent[2 * a + 1] / this->Edge, static_cast<int>(roots[a]) - 1) : 0;
    }
    for (int k = first[2]; k <= last[2]; ++k)
    {
      for (int j = first[1]; j <= last[1]; ++j)
      {
        for (int i = first[0]; i <= last[0]; ++i)
        {
          vtkIdType tree = 0;
          this->Trees->GetIndexFromLevelZeroCoordinates(tree, i, j, k);
          this->Trees->InitializeNonOrientedCursor(cursor, tree);
          if (cursor->HasTree())
          {
            this->fill(cursor, { i * this->Edge, j * this->Edge, k * this->Edge }, this->Edge, dimension);
          }
        }
      }
    }
    image->GetPointData()->AddArray(phi);
    image->GetPointData()->AddArray(distance);
    image->GetPointData()->SetActiveScalars("SignedDistance");
    image->GetFieldData()->ShallowCopy(this->Trees->GetFieldData());
    if (this->Out.Filled != nodes) // the leaves do not overlap: each node is counted once
    {
      vtkErrorMacro("the trees' leaves cover " << this->Out.Filled << " of the piece's " << nodes << " nodes");
      return 0;
    }
    return 1;
  }

private:
  struct Piece
  {
    const int* Extent;
    double* Phi;
    double* Distance;
    vtkIdType Filled; ///< nodes given a value
  };

  vtkDataArray* coordinates(int a) const
  {
    return a == 0 ? this->Trees->GetXCoordinates()
                  : (a == 1 ? this->Trees->GetYCoordinates() : this->Trees->GetZCoordinates());
  }

  /// The nodes of the cell at `cursor` (from node `corner`, `size` per axis)
  /// within the piece take its leaves' values; masked cells lie beyond the grid.
  void fill(vtkHyperTreeGridNonOrientedCursor* cursor, const std::array<int, 3>& corner, int size, int dimension)
  {
    if (cursor->IsMasked())
    {
      return;
    }
    const int* e = this->Out.Extent;
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      const int end = a < dimension ? corner[a] + size - 1 : corner[a];
      lo[a] = std::max(corner[a], e[2 * a]);
      hi[a] = std::min(end, e[2 * a + 1]);
      if (lo[a] > hi[a])
      {
        return;
      }
    }
    if (!cursor->IsLeaf())
    {
      const int half = size / 2;
      for (unsigned char child = 0; child < (1u << dimension); ++child)
      {
        std::array<int, 3> c = corner;
        for (int a = 0; a < dimension; ++a)
        {
          c[a] += ((child >> a) & 1) ? half : 0; // VTK's child index x + 2y (+ 4z)
        }
        cursor->ToChild(child);
        this->fill(cursor, c, half, dimension);
        cursor->ToParent();
      }
      return;
    }
    const vtkIdType id = cursor->GetGlobalNodeIndex();
    const double phi = this->Phi->GetTuple1(id), distance = this->Distance->GetTuple1(id);
    const vtkIdType nx = e[1] - e[0] + 1, ny = e[3] - e[2] + 1;
    for (int k = lo[2]; k <= hi[2]; ++k)
    {
      for (int j = lo[1]; j <= hi[1]; ++j)
      {
        const vtkIdType row = ((k - e[4]) * ny + (j - e[2])) * nx - e[0];
        std::fill(this->Out.Phi + row + lo[0], this->Out.Phi + row + hi[0] + 1, phi);
        std::fill(this->Out.Distance + row + lo[0], this->Out.Distance + row + hi[0] + 1, distance);
        this->Out.Filled += hi[0] - lo[0] + 1;
      }
    }
  }

  vtkHyperTreeGrid* Trees = nullptr;
  vtkDataArray* Phi = nullptr;
  vtkDataArray* Distance = nullptr;
  std::array<long long, 3> Dims{ 1, 1, 1 };
  int Edge = 8;
  Piece Out{};
};
vtkStandardNewMacro(TreeImageSource);
} // namespace

sltk::Status writeTreeImage(
  const std::string& path, vtkHyperTreeGrid* trees, const std::array<long long, 3>& dims, long long pieceNodes)
{
  if (!trees || !trees->GetCellData()->GetArray("SignedDistance") ||
    !trees->GetCellData()->GetArray("DistanceToCloud") || trees->GetBranchFactor() != 2)
  {
    return sltk::Status::invalidArgument("no octree of the reconstruction to write to " + path);
  }
  vtkNew<TreeImageSource> source;
  source->SetTrees(trees, dims, static_cast<int>(sltk::TileEdge)); // a tree per tile, its leaves single nodes
  const long long nodes = dims[0] * dims[1] * dims[2];
  // At least 4 pieces (1 a node at most), so that small grids take the pieces' path too.
  const int pieces = static_cast<int>(std::max((nodes + pieceNodes - 1) / pieceNodes, std::min(4LL, nodes)));
  return writeAtomically(path,
    [&](const std::string& temporary)
    {
      vtkNew<vtkXMLImageDataWriter> writer;
      writer->SetInputConnection(source->GetOutputPort());
      writer->SetNumberOfPieces(pieces); // one extent at a time: the image is never whole
      writer->SetFileName(temporary.c_str());
      useFastXmlData(writer);
      return writer->Write() == 1;
    });
}

} // namespace sltkcli
