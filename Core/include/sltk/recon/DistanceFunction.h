// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file DistanceFunction.h
/// The distance d(x) = min_{Q in P} |x - Q| to the cloud on every grid node
/// (thesis 4.4.2): exact on the nodes of a box of 4^D grid points around each
/// point Q (the 2^D corners of the cell holding Q and one more layer), then
/// fast sweeping (FastSweeping.h) for all other nodes.
///
/// Exact values come from the PointLocator, i.e. the minimum over the whole
/// cloud, computed per node in parallel (order-independent, identical for any
/// number of threads). Memory: the field, one byte per node for the exact
/// mask, and the locator (O(|P|)); work O(|P| 4^D) + O(nodes) per sweep.

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

namespace sltk
{

struct DistanceOptions
{
  int ExactHalfWidth = 2;       ///< the exact box is 2 * ExactHalfWidth nodes per axis (4 in the thesis)
  int Ghost = 2;                ///< ghost layers of the output (filled by linear extrapolation)
  int MaxSweepCycles = 20;      ///< cycles of 2^D sweeps (stops earlier when nothing changes)
  double SweepTolerance = 1e-6; ///< FastSweepingOptions::Tolerance (0: until nothing changes)
};

struct DistanceReport
{
  Index ExactNodes = 0; ///< nodes carrying the exact distance
  int SweepCycles = 0;  ///< cycles the fast sweeping needed
};

/// Computes d on `grid` into `distance` (resized). The cloud must be non-empty;
/// points outside the grid are allowed (their boxes are clipped to it).
template <int D>
Status distanceToCloud(const PointCloud<D>& cloud, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& distance, const DistanceOptions& options = {}, DistanceReport* report = nullptr);

/// The same with the caller's locator (on the cloud it measures): one bucketing per cloud.
template <int D>
Status distanceToCloud(const PointLocator<D>& locator, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& distance, const DistanceOptions& options = {}, DistanceReport* report = nullptr);

/// The same on this rank's slab of `whole` (sltk/grid/Slabs.h, slab.Ghost >= 1):
/// `distance` becomes the window's field (rows slab.First .. slab.Stop - 1 at
/// the whole grid's coordinates); the exact boxes are those of the whole grid
/// (a point's box is clipped to the whole grid, then to the window), and the
/// sweeps exchange their edge rows (FastSweepingSlabs.h). `locator` holds the
/// whole cloud, or at least every point within ExactHalfWidth + 1 rows and two
/// cell diagonals of the window (recon/RunPoints.h): the exact nodes and their
/// values are then the whole cloud's. A collective call; with SweepTolerance 0
/// the one-rank distance up to rounding.
template <int D>
Status distanceToCloudSlabs(const PointLocator<D>& locator, const GridSpec<D>& whole, const SlabPlan& slab,
  const Communicator& comm, const Context& ctx, GridField<D, double>& distance, const DistanceOptions& options = {},
  DistanceReport* report = nullptr);

/// The same on a grid every rank holds whole, from a cloud spread over the
/// ranks by owners (PointOwners.h; halo points count as the cloud's own): the
/// exact boxes of every rank's points (a maximum over the ranks of one mark a
/// node) and at their nodes the nearest point of every rank (a minimum of the
/// marked nodes' distances), then every rank sweeps the whole grid: the
/// one-rank distance bit for bit, for grids small enough to hold on every
/// rank (the automatic K_P's probe, AutomaticParameters.h). Collective.
template <int D>
Status distanceToCloudOnRanks(const OwnedPoints<D>& points, const GridSpec<D>& grid, const Communicator& comm,
  const Context& ctx, GridField<D, double>& distance, const DistanceOptions& options = {},
  DistanceReport* report = nullptr);

extern template Status distanceToCloud(const PointCloud<2>&, const GridSpec<2>&, const Context&, GridField<2, double>&,
  const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloud(const PointCloud<3>&, const GridSpec<3>&, const Context&, GridField<3, double>&,
  const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloud(const PointLocator<2>&, const GridSpec<2>&, const Context&,
  GridField<2, double>&, const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloud(const PointLocator<3>&, const GridSpec<3>&, const Context&,
  GridField<3, double>&, const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloudOnRanks(const OwnedPoints<2>&, const GridSpec<2>&, const Communicator&,
  const Context&, GridField<2, double>&, const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloudOnRanks(const OwnedPoints<3>&, const GridSpec<3>&, const Communicator&,
  const Context&, GridField<3, double>&, const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloudSlabs(const PointLocator<2>&, const GridSpec<2>&, const SlabPlan&,
  const Communicator&, const Context&, GridField<2, double>&, const DistanceOptions&, DistanceReport*);
extern template Status distanceToCloudSlabs(const PointLocator<3>&, const GridSpec<3>&, const SlabPlan&,
  const Communicator&, const Context&, GridField<3, double>&, const DistanceOptions&, DistanceReport*);

} // namespace sltk
