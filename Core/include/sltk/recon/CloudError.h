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
#include "sltk/recon/FarPointSeeds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sltk
{

/// Whether point q's cell row along the last axis (of the whole grid of
/// `rows` rows, the cell clamped into it) is in [firstRow, endRow).
template <int D>
bool pointInRows(const GridSpec<D>& g, const double* q, Index firstRow, Index endRow, Index rows)
{
  const double cell = std::floor((q[D - 1] - g.Origin[D - 1]) / g.Spacing[D - 1]);
  const Index row = static_cast<Index>(std::clamp(cell, 0.0, static_cast<double>(std::max<Index>(rows - 2, 0))));
  return row >= firstRow && row < endRow;
}

/// The sum of term(I[phi](Q)) over the points of `cloud` whose cell row is in
/// [firstRow, endRow) (pointInRows); phi's ghosts filled, its window holding
/// those cells and the interpolation stencil around them.
template <int D, class Interp, class Term>
double sumOverPoints(const GridField<D>& phi, const PointCloud<D>& cloud, const Context& ctx, Index firstRow,
  Index endRow, Index rows, Term term)
{
  const GridSpec<D>& g = phi.spec();
  return ctx.parallelSum(0, cloud.size(),
    [&](Index b, Index e)
    {
      Interp interp(phi); // one per chunk: interpolators hold per-cell scratch
      double s = 0.0;
      for (Index k = b; k < e; ++k)
      {
        const double* q = cloud.Points[static_cast<size_t>(k)].data();
        if (pointInRows(g, q, firstRow, endRow, rows))
        {
          s += term(interpolate(interp, g, q));
        }
      }
      return s;
    });
}

/// The points of those rows with I[phi](Q) > threshold (outside the zero
/// level set by more than it), ascending; serial (a pass over the cloud once a run).
template <int D, class Interp>
std::vector<OutsidePoint> pointsOutside(
  const GridField<D>& phi, const PointCloud<D>& cloud, double threshold, Index firstRow, Index endRow, Index rows)
{
  const GridSpec<D>& g = phi.spec();
  Interp interp(phi);
  std::vector<OutsidePoint> outside;
  for (Index k = 0; k < cloud.size(); ++k)
  {
    const double* q = cloud.Points[static_cast<size_t>(k)].data();
    if (pointInRows(g, q, firstRow, endRow, rows))
    {
      const double v = interpolate(interp, g, q);
      if (v > threshold)
      {
        outside.push_back({ k, v });
      }
    }
  }
  return outside;
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
