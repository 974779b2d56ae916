// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudInitialData.h
/// The initial level set phi0 of the reconstruction (thesis 4.4.4): a signed
/// distance whose zero level set encloses the cloud at distance about
/// gamma_P = K_P h_P (4.5.2, K_P = 2 by default, 10 for scans with holes).
///
///  1. external marking: the nodes on the outer boundary of the grid are
///     external; the marking moves inwards along every Cartesian direction
///     (forward and backward passes on every grid line) and stops at nodes
///     where d(x_i) < gamma_P. The passes over all axes are repeated until
///     nothing changes, so every region reachable from the boundary by an
///     axis-aligned path of nodes with d >= gamma_P is external (the serial
///     equivalent of the thesis's iterated parallel marking, Fig. 4.4);
///  2. phi0 = d - gamma_P on external nodes, a large value elsewhere, fast
///     sweeping recomputes the internal nodes, the sign is reversed inside.
///
/// Where the thesis is silent: the internal values are swept from
/// -(d - gamma_P) (i.e. the sweeping of step 2 is run on -phi0), so that phi0
/// keeps |grad phi0| ~ 1 across the external/internal boundary instead of
/// jumping from ~0+ to ~-dx there. Internal nodes are at least one sweep
/// step from a frozen value, hence phi0 < 0 inside (clamped to <= 0).
///
/// Also the sphere/ellipsoid guesses of the knot test (Ellipsoid.h).

#include "sltk/cloud/PointCloud.h"
#include "sltk/levelset/Ellipsoid.h"

#include <cstdint>
#include <vector>

namespace sltk
{

struct InitialDataOptions
{
  int Ghost = 2;                ///< ghost layers of phi0 (filled by linear extrapolation)
  int MaxSweepCycles = 20;      ///< fast sweeping cycles (stops earlier when nothing changes)
  double SweepTolerance = 1e-6; ///< FastSweepingOptions::Tolerance (0: until nothing changes)
};

struct InitialDataReport
{
  Index ExternalNodes = 0;          ///< nodes marked external
  Index BoundaryBelowThreshold = 0; ///< boundary nodes with d < gamma_P (the cloud touches the boundary)
  int MarkingRounds = 0;            ///< rounds of passes over all axes (the last one changed nothing)
  int SweepCycles = 0;
};

/// Step 1: external[k] = 1 for the external nodes (x-fastest, no ghosts).
template <int D>
Status markExternal(const GridField<D, double>& distance, double threshold, const Context& ctx,
  std::vector<std::uint8_t>& external, int* rounds = nullptr);

/// The widest way out of every node: the largest threshold t for which the
/// marking of step 1 with gamma_P = t reaches it, i.e. the maximum over
/// axis-aligned node paths from the grid's boundary of the minimum of d along
/// the path (+infinity on the boundary). markExternal with threshold t marks
/// exactly the nodes with bottleneck >= t, so one computation answers every
/// K_P at once (AutomaticParameters.h). Computed by adding the nodes in
/// decreasing order of d to the components they join, each node assigned when
/// its component first reaches the boundary (O(n log n) for the sort, one
/// thread).
template <int D>
Status outsideBottleneck(const GridField<D, double>& distance, const Context& ctx, std::vector<double>& bottleneck);

/// Steps 1-2: phi0 from the distance to the cloud and gamma_P = threshold > 0.
template <int D>
Status cloudInitialData(const GridField<D, double>& distance, double threshold, const Context& ctx,
  GridField<D, double>& phi0, const InitialDataOptions& options = {}, InitialDataReport* report = nullptr);

/// The sphere centred at the cloud's bounding-box centre through its farthest
/// point, its radius enlarged by `margin`.
template <int D>
Ellipsoid<D> boundingSphere(const PointCloud<D>& cloud, double margin);

/// The axis-aligned ellipsoid through the corners of the cloud's bounding box
/// (semi-axes sqrt(D) times the half extents), enlarged by `margin`.
template <int D>
Ellipsoid<D> boundingEllipsoid(const PointCloud<D>& cloud, double margin);

extern template Status markExternal(
  const GridField<2, double>&, double, const Context&, std::vector<std::uint8_t>&, int*);
extern template Status markExternal(
  const GridField<3, double>&, double, const Context&, std::vector<std::uint8_t>&, int*);
extern template Status outsideBottleneck(const GridField<2, double>&, const Context&, std::vector<double>&);
extern template Status outsideBottleneck(const GridField<3, double>&, const Context&, std::vector<double>&);
extern template Status cloudInitialData(const GridField<2, double>&, double, const Context&, GridField<2, double>&,
  const InitialDataOptions&, InitialDataReport*);
extern template Status cloudInitialData(const GridField<3, double>&, double, const Context&, GridField<3, double>&,
  const InitialDataOptions&, InitialDataReport*);
extern template Ellipsoid<2> boundingSphere(const PointCloud<2>&, double);
extern template Ellipsoid<3> boundingSphere(const PointCloud<3>&, double);
extern template Ellipsoid<2> boundingEllipsoid(const PointCloud<2>&, double);
extern template Ellipsoid<3> boundingEllipsoid(const PointCloud<3>&, double);

} // namespace sltk
