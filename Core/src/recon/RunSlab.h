// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RunSlab.h
/// The rows of one run's grid that this rank of the reconstruction works on
/// (grid/Slabs.h, Documentation/Distributed.md): its owned rows plus ghost
/// rows on each side, all rows and no ghost row on one rank. Fields live on
/// the window (GridSpec::Offset places it in the run's grid); band node lists
/// hold window node numbers. The ghost rows cover the stencils of the band
/// and of the usual feet of one SL step; the feet beyond them go to their
/// owners in one batched exchange per step (FarFeetExchange.h, thesis 4.4.1).

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Communicator.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/SlabExchange.h"
#include "sltk/grid/Slabs.h"
#include "sltk/levelset/NarrowBand.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/SlabPolicy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sltk
{

template <int D>
class RunSlab
{
public:
  explicit RunSlab(const Communicator& comm)
    : Comm(&comm)
  {
  }

  /// This rank's slab of `whole` with SlabGhostRows ghost rows (none on one
  /// rank), cut by slabBoundaries (SlabPolicy.h): run 1 by the cloud's points
  /// and rows, a later run (`previous`, the run before) near where the
  /// previous run's slabs meet, moved towards equal shares of its band
  /// (recordBand()) as far as each rank's owned rows stay in its previous
  /// window (transfer()).
  Status plan(const GridSpec<D>& whole, const PointCloud<D>& cloud, const RunSlab* previous = nullptr)
  {
    this->Whole = whole;
    this->RowNodes = whole.nodeCount() / whole.Dims[D - 1];
    this->Boundaries = slabBoundaries(whole, this->Comm->size(), cloud, previous ? &previous->Whole : nullptr,
      previous ? &previous->Boundaries : nullptr,
      previous && !previous->BandRows.empty() ? &previous->BandRows : nullptr);
    this->BandRows.clear();
    return planSlabAt(this->Boundaries, this->distributed() ? SlabGhostRows : 0, this->Comm->rank(),
      "the SL step's feet and the interpolation stencil", this->Slab);
  }

  bool distributed() const { return this->Comm->size() > 1; }
  const Communicator& comm() const { return *this->Comm; }
  const SlabPlan& slab() const { return this->Slab; }
  const GridSpec<D>& whole() const { return this->Whole; }
  Index rows() const { return this->Whole.Dims[D - 1]; }

  /// The window's grid: rows slab.First .. slab.Stop - 1 of the whole grid.
  GridSpec<D> window() const
  {
    GridSpec<D> spec = this->Whole;
    spec.Dims[D - 1] = this->Slab.windowRows();
    spec.Offset[D - 1] = this->Whole.Offset[D - 1] + this->Slab.First;
    return spec;
  }

  /// Window node numbers of the owned rows: [ownedBegin(), ownedEnd()).
  Index ownedBegin() const { return (this->Slab.Begin - this->Slab.First) * this->RowNodes; }
  Index ownedEnd() const { return (this->Slab.End - this->Slab.First) * this->RowNodes; }

  /// Keeps the nodes of the owned rows (window numbering, ascending).
  void keepOwned(NodeList& nodes) const
  {
    const Index b = this->ownedBegin(), e = this->ownedEnd();
    nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [b, e](Index k) { return k < b || k >= e; }), nodes.end());
  }

  /// The band nodes (|phi| < gamma) of the `depth` ghost rows next to the
  /// owned rows on each side, ascending (none on one rank).
  void ghostBand(const GridField<D>& phi, double gamma, Index depth, NodeList& ghosts) const
  {
    ghosts.clear();
    const auto scan = [&](Index firstRow, Index rows)
    {
      forEachRowLine(phi, firstRow, rows,
        [&](const double* line, Index length, Index node)
        {
          for (Index x = 0; x < length; ++x)
          {
            if (std::fabs(line[x]) < gamma)
            {
              ghosts.push_back(node + x);
            }
          }
        });
    };
    const Index below = this->Slab.Begin - this->Slab.First, above = this->Slab.Stop - this->Slab.End;
    const Index rowsBelow = std::min(below, depth), rowsAbove = std::min(above, depth);
    scan(below - rowsBelow, rowsBelow);
    scan(this->Slab.End - this->Slab.First, rowsAbove);
  }

  /// Overwrites the ghost rows (or the `depth` nearest the owned rows) with the
  /// owners' values (collective; nothing on one rank).
  void exchange(GridField<D>& field, Index depth = std::numeric_limits<Index>::max()) const
  {
    exchangeGhostRows(field, this->Slab, *this->Comm, nullptr, depth);
  }

  /// The same status on every rank (the first failure's); as given on one rank.
  Status agree(const Status& status) const { return this->Comm->agree(status); }

  double sum(double value) const { return this->Comm->allReduce(value, ReduceOp::Sum); }

  double max(double value) const { return this->Comm->allReduce(value, ReduceOp::Max); }

  /// Records the band (|phi| < gamma) of phi's owned rows, nodes per row of
  /// the whole grid summed over the ranks, for the next run's cut (plan()).
  /// A collective call; nothing on one rank.
  void recordBand(const GridField<D>& phi, double gamma)
  {
    if (!this->distributed())
    {
      return;
    }
    this->BandRows.assign(static_cast<size_t>(this->rows()), 0.0);
    for (Index row = this->Slab.Begin; row < this->Slab.End; ++row)
    {
      double& count = this->BandRows[static_cast<size_t>(row)];
      forEachRowLine(phi, row - this->Slab.First, 1,
        [&](const double* line, Index length, Index)
        {
          for (Index x = 0; x < length; ++x)
          {
            count += std::fabs(line[x]) < gamma ? 1.0 : 0.0;
          }
        });
    }
    this->Comm->allReduce(this->BandRows.data(), this->BandRows.size(), ReduceOp::Sum);
  }

  /// Every rank's first row, and the row count.
  const std::vector<Index>& boundaries() const { return this->Boundaries; }

  /// The window's frame for the far feet of a step (FarFeet, LevelSetStep.h).
  void frameFarFeet(FarFeet<D>& far) const
  {
    far.LowEdge = this->Slab.First == 0;
    far.HighEdge = this->Slab.Stop == this->rows();
  }

private:
  const Communicator* Comm;
  GridSpec<D> Whole;
  SlabPlan Slab;
  std::vector<Index> Boundaries; ///< every rank's first row, and the row count
  std::vector<double> BandRows;  ///< band nodes per row over the ranks (recordBand())
  Index RowNodes = 0;
};

} // namespace sltk
