// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Ellipsoid.h
/// An axis-aligned ellipsoid (a sphere when the semi-axes are equal) and its
/// exact signed distance (negative inside): the alternative initial guess of
/// the knot test (thesis 4.5.4, Fig. 4.15, "an ellipsoid encompassing the
/// dataset"). The distance is computed as in D. Eberly, "Distance from a
/// point to an ellipse, an ellipsoid, or a hyperellipsoid" (bisection on the
/// Lagrange multiplier, with the degenerate cases on the coordinate planes).

#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"

#include <array>

namespace sltk
{

template <int D>
struct Ellipsoid
{
  std::array<double, D> Centre{};
  std::array<double, D> SemiAxes{}; ///< > 0
};

/// Signed distance from x to the ellipsoid's surface (negative inside).
template <int D>
double signedDistance(const Ellipsoid<D>& e, const double* x);

/// phi0 = signed distance to the ellipsoid on every node (ghosts filled by
/// extrapolation). Fails on non-positive or non-finite semi-axes.
template <int D>
Status ellipsoidLevelSet(const Ellipsoid<D>& e, const GridSpec<D>& grid, const Context& ctx,
  GridField<D, double>& phi0, int ghost = 2);

extern template double signedDistance(const Ellipsoid<2>&, const double*);
extern template double signedDistance(const Ellipsoid<3>&, const double*);
extern template Status ellipsoidLevelSet(const Ellipsoid<2>&, const GridSpec<2>&, const Context&,
  GridField<2, double>&, int);
extern template Status ellipsoidLevelSet(const Ellipsoid<3>&, const GridSpec<3>&, const Context&,
  GridField<3, double>&, int);

} // namespace sltk
