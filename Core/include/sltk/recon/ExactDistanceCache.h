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

#include "sltk/cloud/PointLocator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/levelset/NarrowBand.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace sltk
{

template <int D>
class ExactDistanceCache
{
public:
  /// The cloud and its locator must outlive the cache.
  ExactDistanceCache(const PointCloud<D>& cloud, const PointLocator<D>& locator)
    : Cloud(&cloud)
    , Locator(&locator)
  {
  }

  /// Forgets what was computed (a new grid or a new field); dist needs one ghost layer.
  void reset(const GridField<D>& dist)
  {
    this->Exact.reset(new std::atomic<std::uint8_t>[dist.storage().size()]()); // all zero
  }

  /// Makes d exact on the band's stencils; returns how many nodes were computed.
  Index ensure(const NodeList& band, const Context& ctx, GridField<D>& dist);

private:
  const PointCloud<D>* Cloud;
  const PointLocator<D>* Locator;
  static constexpr std::uint8_t SlotExact = 1;    ///< d is exact there (or claimed by the call computing it)
  static constexpr std::uint8_t StencilExact = 2; ///< the node's whole stencil is SlotExact
  /// Per storage slot: SlotExact | StencilExact flags.
  std::unique_ptr<std::atomic<std::uint8_t>[]> Exact;
};

extern template class ExactDistanceCache<2>;
extern template class ExactDistanceCache<3>;

} // namespace sltk
