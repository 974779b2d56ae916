// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file TiledMemory.h
/// The memory the tiled reconstruction (TiledReconstruction.h) needs, known
/// before it runs: run 1's uniform grid, and the finest run's tiles, which
/// lie where the front is, that is near the cloud's points.

#include "sltk/cloud/PointCloud.h"
#include "sltk/grid/GridSpec.h"

#include <vector>

namespace sltk
{

/// Peak bytes of the tiled reconstruction per node stored in a tile: the
/// tiles' phi and d (16), the reinitialisation's and the step's arrays on the
/// band, the scratch copies. Measured: 44 on the Stanford bunny (330 MB for
/// 7.46M stored nodes, run 1's grid included), 46 on the full dragon (2.42 GB
/// for 52.7M); 48 leaves room.
constexpr double TiledBytesPerStoredNode = 48.0;

/// Nodes the finest run (the last grid) will store, estimated from the
/// cloud: the tiles of 8^D nodes that hold a point or lie next to one that
/// does (the band is a few nodes thick around the front, which lies within a
/// few spacings of the points). Above what the run stores on the sphere, the
/// bunny and the dragon (7.47M for 7.46M, 53.8M for 52.7M, measured before
/// the runs freed the tiles the band left; the bunny at --cdx 2 --kp 10 now
/// stores 4.73M at its end for 7.48M estimated, 2026-11-26); 3% below on the
/// 64-point circle, whose front passes farther than a tile from its points.
/// `sltk info --octree` prints it per run.
template <int D>
double estimatedTiledNodes(const PointCloud<D>& cloud, const GridSpec<D>& finest);

extern template double estimatedTiledNodes(const PointCloud<2>&, const GridSpec<2>&);
extern template double estimatedTiledNodes(const PointCloud<3>&, const GridSpec<3>&);

} // namespace sltk
