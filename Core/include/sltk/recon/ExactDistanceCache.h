// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ExactDistanceCache.h
/// Exact distance to the cloud where the level-set step needs it, computed on
/// demand. The thesis sweeps d over the whole grid (4.4.2) because its cloud
/// is distributed; here the whole cloud is at hand, so the nodes the step and
/// the energy read (band nodes, their face neighbours for grad d, the other
/// corners of their cells for (4.29)/(4.30)) get the exact nearest-point
/// distance the first time the band reaches them. Elsewhere d keeps its
/// approximate value (swept in run 1, interpolated from the previous run
/// later). Work: O(new nodes) nearest-point queries per iteration, the new
/// nodes grouped by boxes of 4^D nodes and each box's distances found with one
/// search (PointLocator::nearestDistances, bit for bit the per-node query);
/// a band node whose stencil is already exact costs one flag read.
///
/// On slabs a rank's locator may hold only the points within `reach` of its
/// window (recon/RunPoints.h): a distance found there that is at most reach is
/// the whole cloud's; the farther ones are settled over the ranks (every rank
/// computes them from its points, the minimum is taken), so ensure() is then a
/// collective call.

#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/levelset/NarrowBand.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace sltk
{

template <int D>
class ExactDistanceCache
{
public:
  /// The locator (on the whole cloud) must outlive the cache, or its next bind().
  explicit ExactDistanceCache(const PointLocator<D>& locator)
    : Locator(&locator)
  {
  }

  /// Queries `locator`, which holds every point within `reach` of the nodes
  /// ensure() is given; the farther distances are settled over `comm`'s ranks
  /// (every rank must then call ensure() as often). Both must outlive the cache's use.
  void bind(const PointLocator<D>& locator, double reach, const Communicator& comm)
  {
    this->Locator = &locator;
    this->Reach = reach;
    this->Comm = &comm;
  }

  /// Forgets what was computed (a new grid or a new field); dist needs one ghost layer.
  void reset(const GridField<D>& dist)
  {
    this->Exact.reset(new std::atomic<std::uint8_t>[dist.storage().size()]()); // all zero
  }

  /// Makes d exact on the band's stencils; returns how many nodes were computed.
  Index ensure(const NodeList& band, const Context& ctx, GridField<D>& dist);

private:
  /// The slots of `pending` whose distance exceeds Reach take the least over the ranks.
  void settleBeyondReach(const std::vector<std::vector<Index>>& pending, const std::array<Index, D>& padded,
    const Context& ctx, GridField<D>& dist) const;

  const PointLocator<D>* Locator;
  double Reach = std::numeric_limits<double>::infinity();
  const Communicator* Comm = nullptr;
  static constexpr std::uint8_t SlotExact = 1;    ///< d is exact there (or claimed by the call computing it)
  static constexpr std::uint8_t StencilExact = 2; ///< the node's whole stencil is SlotExact
  /// Per storage slot: SlotExact | StencilExact flags.
  std::unique_ptr<std::atomic<std::uint8_t>[]> Exact;
};

extern template class ExactDistanceCache<2>;
extern template class ExactDistanceCache<3>;

} // namespace sltk
