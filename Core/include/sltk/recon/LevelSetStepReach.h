// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LevelSetStepReach.h
/// How far the feet of one step of (4.9) (LevelSetStep.h) lie from their
/// nodes along the last axis: the bound a slab decomposition (grid/Slabs.h)
/// needs for its ghost rows, so that every foot of an owned node falls in the
/// rank's window and no foot needs a remote request (thesis 4.4.1). Per band
/// node, |x*_ij - x_i|_last <= C dt |grad d|_last + sqrt(2 C eta d dt / p)
/// sqrt(D - 1) (the tangent frame sigma is orthonormal and xi_j in {+-1}^(D-1)),
/// C the scale factor (4.32); with tunnel detection grad phi may replace
/// grad d. Work O(band).

#include "sltk/recon/LevelSetStep.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace sltk
{

/// The largest foot displacement along the last axis over `band`, in cells of
/// that axis (phi's and dist's ghost layers filled). Parallel over the band.
template <int D>
double levelSetStepReach(const GridField<D>& phi, const GridField<D>& dist, const NodeList& band,
  const LevelSetStepParameters& par, const Context& ctx = {})
{
  const double h = phi.spec().Spacing[D - 1];
  const Index s = phi.strides()[D - 1];
  std::atomic<double> reach{ 0.0 };
  ctx.parallelFor(0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      double chunk = 0.0;
      for (Index k = b; k < e; ++k)
      {
        const auto i = phi.nodeIndex(band[static_cast<size_t>(k)]);
        const double* pp = phi.pointer(i);
        const double* pd = dist.pointer(i);
        const double d = *pd;
        const double scale = cutOff(*pp, par.Widths) * (par.P == 1.0 ? 1.0 : std::pow(d / par.Energy, par.P - 1.0));
        double speed = std::fabs(pd[s] - pd[-s]) / (2.0 * h);
        if (par.DetectTunnels)
        {
          speed = std::max(speed, std::fabs(pp[s] - pp[-s]) / (2.0 * h));
        }
        const double spread = std::sqrt(std::max(0.0, 2.0 * scale * par.Eta * d * par.TimeStep / par.P));
        chunk = std::max(chunk, (scale * par.TimeStep * speed + spread * std::sqrt(D - 1.0)) / h);
      }
      double seen = reach.load();
      while (chunk > seen && !reach.compare_exchange_weak(seen, chunk))
      {
      }
    });
  return reach.load();
}

} // namespace sltk
