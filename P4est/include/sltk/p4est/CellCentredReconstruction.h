// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file CellCentredReconstruction.h
/// The thesis's own adaptive reconstruction (chapter 5), distributed over
/// MPI ranks by p4est's partition: a p4est quadtree (2D) or p8est octree (3D)
/// whose leaves carry phi and d at their centres (5.1.2),
/// adapted every iteration (refine where |phi| < beta, coarsen where flat,
/// 2:1 balance; new values from the parent's polynomial, 5.2.2, (5.6)), the
/// SL step (5.4) with feet located in the tree (a hash table of a rank's
/// leaves and ghosts where the thesis uses p4est_search_local, CellTree.h;
/// the feet in other ranks' leaves answered by their owners in one batched
/// exchange per step, PointValues.h) and interpolated by
/// the least-squares Q1 polynomial of the leaf they fall in (5.5),
/// derivatives from the leaf's polynomial, d by the propagation (5.8)-(5.9),
/// and Saye's closest-point reinitialisation followed by the propagation of
/// the reinitialised values (5.2.4). One more level per run (5.10)-(5.12).
///
/// It exists to compare like for like with the thesis's chapter 5 tables
/// (bench/BenchP4estCellCentred.cxx, Documentation/Octree.md); the library's
/// octree output (vtkOctreeSDF, `--octree`) is the tiled band, which keeps a
/// continuous zero level set. On any number of ranks it gives what it gives
/// on one: the same leaves, iterations and values (sums are added in the
/// one-rank order; Documentation/Octree.md).

#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/p4est/CellPolynomial.h"
#include "sltk/recon/ReconstructionPlan.h"

#include <cstdint>
#include <vector>

namespace sltk
{
namespace p4est
{

/// Memory of one leaf while an iteration runs: p4est's quadrant with phi and
/// its polynomial, the neighbour lists, the polynomials of phi and d, the
/// propagation's state (measured: 1,205 bytes, 4.06 GB at the peak of
/// Cube&Spheres' run 3 with 3.37M leaves).
constexpr double CellCentredBytesPerLeaf = 1300.0;

struct CellCentredOptions
{
  /// Delta x_min of run 1 (unit-box units): Delta_P / 2^L0 with L0 of (5.10).
  double FirstCellSize = 0.0;
  int MinimumLevel = 2; ///< the coarsest leaves of the tree
  /// Bytes a rank's part of the tree may take (CellCentredBytesPerLeaf a leaf); 0: the memory available.
  std::uint64_t MemoryBudget = 0;
};

/// One leaf of the final tree.
template <int D>
struct CellCentredLeaf
{
  std::array<double, D> Centre{};
  double Size = 0.0;
  int Level = 0;
  double Phi = 0.0;
  double Distance = 0.0;
  CellPolynomial<D> Polynomial; ///< least-squares Q1 of phi (5.5)
};

/// Energies and errors are in the user's units, as the other reconstructions
/// report them (Reconstruction.h recordsToUser).
struct CellCentredIteration
{
  int Run = 0;
  int Iteration = 0;
  double Energy = 0.0;     ///< E_2 (4.33) of phi^n
  double CloudError = 0.0; ///< Err_P (4.35) of phi^{n+1}
  Index Leaves = 0;        ///< leaves of T^{n+1}
  Index FinestLeaves = 0;  ///< of them, at the run's level
  Index UniformCells = 0;  ///< the uniform grid of the run's level over the tree's cube
};

struct CellCentredRun
{
  int Run = 0;
  int Level = 0;
  double CellSize = 0.0; ///< Delta x_min (5.1), unit-box units
  int Iterations = 0;
  int TreeChanges = 0; ///< iterations whose adaptation changed the leaves (the others reuse d and the fits)
  double Energy = 0.0;
  double CloudError = 0.0;
};

/// The leaves and the tree's cube are in unit-box units (4.5): `Box` maps them.
template <int D>
struct CellCentredResult
{
  UnitBox<D> Box;
  std::array<double, D> DomainOrigin{}; ///< the tree's cube
  double DomainEdge = 0.0;
  std::vector<CellCentredRun> Runs;
  std::vector<CellCentredIteration> History;
  std::vector<CellCentredLeaf<D>> Leaves;
};

/// Runs plan.Options.Runs runs on the plan's cloud (unit box, the whole
/// cloud on every rank), from its initial ellipsoid
/// (InitialGuess::BoundingSphere or BoundingEllipsoid), with its schedule,
/// beta and gamma factors and stopping rule, over the ranks of `comm`
/// (collective: every rank passes the same plan). result.Leaves holds this
/// rank's leaves; the runs and the history are every rank's. Refused
/// (outOfMemory) when a rank's part of the tree outgrows its memory; a
/// failure on one rank is returned on every rank.
template <int D>
Status reconstructCellCentred(const ReconstructionPlan<D>& plan, const CellCentredOptions& options, const Context& ctx,
  CellCentredResult<D>& result, const Communicator& comm = serialCommunicator());

extern template Status reconstructCellCentred(
  const ReconstructionPlan<2>&, const CellCentredOptions&, const Context&, CellCentredResult<2>&, const Communicator&);
extern template Status reconstructCellCentred(
  const ReconstructionPlan<3>&, const CellCentredOptions&, const Context&, CellCentredResult<3>&, const Communicator&);

} // namespace p4est
} // namespace sltk
