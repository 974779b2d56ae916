// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file BrickGeometry.h
/// Where the trees of a forest lie (thesis 5.1: a forest is a macro-mesh of
/// cubes Omega'_k, one tree each): a brick of nx x ny x nz cubic trees of one
/// edge over the padded bounding box of a cloud, so that a box that is not a
/// cube is not covered by one large cube (the thesis uses a single tree over
/// a cubic domain, 5.2). Coordinates are those of the caller (P4est/ uses the
/// unit box of recon/UnitBox.h).

#include "sltk/cloud/PointCloud.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace sltk
{
namespace p4est
{

/// At most this many trees along an axis: a very flat box gets trees of at
/// least 1/MaxTreesPerAxis of its longest side rather than thousands of trees.
constexpr int MaxTreesPerAxis = 16;

struct BrickGeometry
{
  std::array<double, 3> Origin{}; ///< lower corner of the brick
  double TreeEdge = 1.0;          ///< edge of every tree (a cube)
  std::array<int, 3> Trees{ { 1, 1, 1 } };

  int treeCount() const { return this->Trees[0] * this->Trees[1] * this->Trees[2]; }
  /// Edge of a leaf of `level`: Delta x_min of (5.1) for level = L.
  double cellSize(int level) const { return std::ldexp(this->TreeEdge, -level); }
  /// Cells of the uniform grid of the same finest level over the brick.
  double uniformCells(int level) const { return this->treeCount() * std::ldexp(1.0, 3 * level); }
};

/// The brick over `box` padded on every side by `padding` times its largest
/// extent, centred on the box: of the edges that split one padded extent into
/// n trees and are no shorter than the smallest padded extent (one tree
/// across the thinnest axis) nor than 1/MaxTreesPerAxis of the largest, the
/// one whose brick has the least volume.
BrickGeometry brickOver(const Box<3>& box, double padding);

} // namespace p4est
} // namespace sltk
