// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudThickness.h
/// How flat a cloud is: the least-squares plane (3D) or line (2D) through it,
/// from its principal axes, and the largest distance of a point from that
/// plane or line. A cloud thinner than the grid's finest cell (a disc or a
/// ring in a tilted plane, a scanned sheet) encloses no volume the level set
/// (4.9) can resolve: the front has no cell to stay in and vanishes, whatever
/// K_P or eta (ReconstructionPlan.h refuses it up front, with this fit).

#include "sltk/cloud/PointCloud.h"

#include <array>

namespace sltk
{

template <int D>
struct FlatFit
{
  std::array<double, D> Centre{}; ///< the centroid
  std::array<double, D> Normal{}; ///< unit normal of the plane (3D) or line (2D): the least-variance axis
  double Thickness = 0.0;         ///< largest |(p - Centre) . Normal| over the cloud
};

/// The principal-axes fit of a non-empty cloud (finite coordinates).
template <int D>
FlatFit<D> fitFlat(const PointCloud<D>& cloud);

extern template FlatFit<2> fitFlat(const PointCloud<2>&);
extern template FlatFit<3> fitFlat(const PointCloud<3>&);

} // namespace sltk
