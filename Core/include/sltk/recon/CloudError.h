// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CloudError.h
/// Err_P (4.35), the mean of |I[phi](Q)| over the cloud, as a sum that a slab
/// decomposition (grid/Slabs.h) splits: each rank sums the points whose cell
/// lies in its owned rows, and the sums are added over the ranks.

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/interp/Interpolator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sltk
{

/// The sum of term(I[phi](Q)) over the points of `cloud` whose cell row along
/// the last axis (of the whole grid of `rows` rows, the cell clamped into it)
/// is in [firstRow, endRow); phi's ghosts filled, its window holding those
/// cells and the interpolation stencil around them.
template <int D, class Interp, class Term>
double sumOverPoints(const GridField<D>& phi, const PointCloud<D>& cloud, const Context& ctx, Index firstRow,
  Index endRow, Index rows, Term term)
{
  const GridSpec<D>& g = phi.spec();
  return ctx.parallelSum(0, cloud.size(),
    [&](Index b, Index e)
    {
      Interp interp(phi);
      double s = 0.0;
      for (Index k = b; k < e; ++k)
      {
        const double* q = cloud.Points[static_cast<size_t>(k)].data();
        const double cell = std::floor((q[D - 1] - g.Origin[D - 1]) / g.Spacing[D - 1]);
        const Index row = static_cast<Index>(std::clamp(cell, 0.0, static_cast<double>(std::max<Index>(rows - 2, 0))));
        if (row >= firstRow && row < endRow)
        {
          s += term(interpolate(interp, g, q));
        }
      }
      return s;
    });
}

/// The sum of |I[phi](Q)| over those points (Err_P times the cloud's size);
/// the defaults take every point.
template <int D, class Interp>
double cloudErrorSum(const GridField<D>& phi, const PointCloud<D>& cloud, const Context& ctx, Index firstRow = 0,
  Index endRow = std::numeric_limits<Index>::max(), Index rows = std::numeric_limits<Index>::max())
{
  return sumOverPoints<D, Interp>(phi, cloud, ctx, firstRow, endRow, rows, [](double v) { return std::fabs(v); });
}

} // namespace sltk
