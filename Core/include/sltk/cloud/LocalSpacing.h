// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LocalSpacing.h
/// Beyond the thesis, whose model has one resolution h_P (4.36) for the whole
/// cloud: how much sparser than usual the cloud is around each point. CAD
/// meshes' vertices and scans seen at a grazing angle are sampled an order of
/// magnitude more sparsely in places; one K_P h_P (4.4.4) then either lets the
/// initial surface leak through the sparse regions or closes the handles of the
/// dense ones (Documentation/Numerics.md, "Local offset").
///
/// For each point Q: s(Q) is the density spacing at its k-th neighbour
/// (CloudSpacing.h), smoothed as the median of s over Q and its k neighbours;
/// the sparsity factor is rho(Q) = s(Q) / median_P s, clamped to
/// [1, MaximumSparsity]: 1 on an evenly sampled cloud (measured: the 99th
/// percentile is at most 1.2 on the Stanford bunny, kitten and fandisk), larger
/// where the sampling is sparser than the cloud's median. The unsmoothed s also
/// sets how far the cloud's points are linked into components (recon/PointClusters.h).

#include "sltk/cloud/PointLocator.h"
#include "sltk/cloud/PointOwners.h"
#include "sltk/exec/Context.h"

#include <vector>

namespace sltk
{

/// The largest sparsity factor used: the initial surface lies at most this many
/// K_P h_P from the cloud (run 1's grid is padded for it).
constexpr double MaximumSparsity = 4.0;

/// s(Q), the density spacing at the k-th neighbour (CloudSpacing.h), unsmoothed, for
/// every point of the locator's cloud, in its order; `neighbours`, when given, gets
/// each point's k nearest, nearest first (k per point). Deterministic for any number
/// of threads. Fails for k < 1 or a cloud of at most k points.
template <int D>
Status densitySpacings(const PointLocator<D>& locator, int k, const Context& ctx, std::vector<double>& spacing,
  std::vector<std::int64_t>* neighbours = nullptr);

/// The median of `values` (the upper middle value of an even count); 0 for none.
double medianOf(std::vector<double> values);

/// rho(Q) for every point of the locator's cloud, in its order, with k
/// neighbours (16, the density spacing's). Deterministic for any number of
/// threads. Clouds of at most k points get 1 everywhere.
template <int D>
Status sparsityFactors(const PointLocator<D>& locator, int k, const Context& ctx, std::vector<double>& factors);

/// densitySpacings() of a cloud spread over the ranks by owners (PointOwners.h):
/// `spacing` holds s(Q) of this rank's own points, `own` their places in
/// points.Cloud (ascending), bit for bit the one-rank values; a query that read
/// beyond the halo is asked again of the ranks its ball reaches (`remote`
/// counts those over every rank). `heldLocator`: one already built on
/// points.Cloud (else one is built here). Fails on every rank, as
/// densitySpacings does, for k < 1 or a cloud of at most k points. Collective.
template <int D>
Status densitySpacingsOnRanks(const OwnedPoints<D>& points, int k, const Communicator& comm, const Context& ctx,
  std::vector<std::int64_t>& own, std::vector<double>& spacing, std::int64_t& remote,
  const PointLocator<D>* heldLocator = nullptr);

/// sparsityFactors() of a cloud spread over the ranks by owners (PointOwners.h),
/// one factor per held point (1 at the halo's): each owner finds its points'
/// k nearest (asking the ranks a ball reaches when it leaves the halo, counted
/// in `remote` over every rank), gets the neighbours' s from their owners and
/// takes the median of the smoothed s as an exact order statistic over the
/// ranks, so every owned point gets the one-rank factor bit for bit. The
/// smoothing runs `batch` owned points at a time (their neighbours found again
/// and held as candidates, 40 bytes each, only for the batch). Collective.
template <int D>
Status sparsityFactorsOnRanks(const OwnedPoints<D>& points, int k, const Communicator& comm, const Context& ctx,
  std::vector<double>& factors, std::int64_t* remote = nullptr, std::int64_t batch = 32768);

extern template Status densitySpacings(
  const PointLocator<2>&, int, const Context&, std::vector<double>&, std::vector<std::int64_t>*);
extern template Status densitySpacings(
  const PointLocator<3>&, int, const Context&, std::vector<double>&, std::vector<std::int64_t>*);
extern template Status sparsityFactors(const PointLocator<2>&, int, const Context&, std::vector<double>&);
extern template Status sparsityFactors(const PointLocator<3>&, int, const Context&, std::vector<double>&);
extern template Status densitySpacingsOnRanks(const OwnedPoints<2>&, int, const Communicator&, const Context&,
  std::vector<std::int64_t>&, std::vector<double>&, std::int64_t&, const PointLocator<2>*);
extern template Status densitySpacingsOnRanks(const OwnedPoints<3>&, int, const Communicator&, const Context&,
  std::vector<std::int64_t>&, std::vector<double>&, std::int64_t&, const PointLocator<3>*);
extern template Status sparsityFactorsOnRanks(
  const OwnedPoints<2>&, int, const Communicator&, const Context&, std::vector<double>&, std::int64_t*, std::int64_t);
extern template Status sparsityFactorsOnRanks(
  const OwnedPoints<3>&, int, const Communicator&, const Context&, std::vector<double>&, std::int64_t*, std::int64_t);

} // namespace sltk
