// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReinitInterface.h
/// The nodes next to the front in the constrained reinitialisation (thesis
/// 1.5.2), all computed on the initial data phi0 (the tilde-phi of the text)
/// from its 3^D blocks (ReinitStencil::block):
///  - the set X of nodes with a sign change towards an axis neighbour (1.38);
///  - the explicit distance d = phi0 / |D phi0| (1.37), central differences;
///  - the split of X into R1 (kappa phi0 < 0, or kappa = 0 and phi0 < 0) and
///    R2 (1.45) by the sign of the mean curvature kappa = div(grad phi0 / |grad phi0|);
///  - Hartmann et al.'s least-squares value (1.44) on R2, the average over the
///    neighbours alpha across the front of r^alpha d^alpha, r^alpha = phi0 / phi0^alpha
///    (1.40), with d^alpha from (1.37): the "one step procedure" of Fig. 4.5.
///
/// Safeguard (not in the text): |d| of (1.37) is capped by the distance from
/// the node to the nearest crossing of the front on its grid edges, found by
/// linear interpolation (1.40). That crossing is a point of the front (up to
/// the O(dx^2) interpolation error), so the cap bounds the distance. On smooth
/// data both estimates are O(dx^2)-accurate and the cap moves (1.37) by that
/// much on some nodes (on the outer, convex side of a circle, which (1.44)
/// then overrides); it matters at kinks and under-resolved features, where
/// the central |D phi0| is far too small (0 at the middle of a feature one
/// cell thick) and (1.37) would throw the node cells away from the front.

#include "sltk/levelset/ReinitStencil.h"

#include <cmath>
#include <limits>

namespace sltk
{

/// The node and its axis neighbours out of its 3^D block, in the layout of
/// ReinitStencil::axes() (u[0] the node, u[1 + 2a] = i - e_a, u[2 + 2a] = i + e_a).
template <int D>
inline void axesOfBlock(const double* block, double* u)
{
  constexpr int c = ReinitStencil<D>::Centre;
  u[0] = block[c];
  for (int a = 0; a < D; ++a)
  {
    const int s = ReinitStencil<D>::blockStride(a);
    u[1 + 2 * a] = block[c - s];
    u[2 + 2 * a] = block[c + s];
  }
}

/// (1.38) from the axis neighbourhood u (ReinitStencil::axes()): the node or an
/// axis neighbour is on the front (phi0_i phi0_alpha <= 0).
template <int D>
inline bool axesAdjacentToInterface(const double* u)
{
  for (int a = 0; a < D; ++a)
  {
    if (u[0] * u[1 + 2 * a] <= 0.0 || u[0] * u[2 + 2 * a] <= 0.0)
    {
      return true;
    }
  }
  return false;
}

/// |D phi0| at the node by central differences, from its axis neighbourhood u.
template <int D>
inline double axesCentralGradientNorm(const double* u, const double* inverseSpacing)
{
  double sum = 0.0;
  for (int a = 0; a < D; ++a)
  {
    const double g = 0.5 * (u[2 + 2 * a] - u[1 + 2 * a]) * inverseSpacing[a];
    sum += g * g;
  }
  return std::sqrt(sum);
}

/// (1.38) from the node's 3^D block.
template <int D>
inline bool adjacentToInterface(const double* block)
{
  double u[ReinitStencil<D>::AxisSize];
  axesOfBlock<D>(block, u);
  return axesAdjacentToInterface<D>(u);
}

/// |D phi0| at the node by central differences, from its 3^D block.
template <int D>
inline double centralGradientNorm(const double* block, const double* inverseSpacing)
{
  double u[ReinitStencil<D>::AxisSize];
  axesOfBlock<D>(block, u);
  return axesCentralGradientNorm<D>(u, inverseSpacing);
}

/// Explicit signed distance (1.37) of a node of X, capped by the distance to
/// the nearest edge crossing (see the file comment).
template <int D>
inline double interfaceDistance(const double* block, const double* inverseSpacing, const double* spacing)
{
  constexpr int c = ReinitStencil<D>::Centre;
  const double phi = block[c];
  if (phi == 0.0)
  {
    return 0.0;
  }
  double cap = std::numeric_limits<double>::infinity();
  for (int a = 0; a < D; ++a)
  {
    const int s = ReinitStencil<D>::blockStride(a);
    for (int side = -1; side <= 1; side += 2)
    {
      const double other = block[c + side * s];
      if (phi * other <= 0.0)
      {
        cap = std::fmin(cap, spacing[a] * std::fabs(phi) / (std::fabs(phi) + std::fabs(other)));
      }
    }
  }
  const double gradient = centralGradientNorm<D>(block, inverseSpacing);
  if (std::isnan(gradient))
  {
    return gradient; // a NaN neighbour is reported, not capped away
  }
  const double d = std::fmin(gradient > 0.0 ? std::fabs(phi) / gradient : cap, cap);
  return std::isfinite(d) ? std::copysign(d, phi) : phi;
}

/// |grad phi0|^3 times the mean curvature div(grad phi0 / |grad phi0|), central
/// differences: sum_a phi_aa sum_{b != a} phi_b^2 - 2 sum_{a < b} phi_a phi_b phi_ab.
template <int D>
inline double curvatureNumerator(const double* block, const double* inverseSpacing)
{
  constexpr int c = ReinitStencil<D>::Centre;
  double g[D];
  for (int a = 0; a < D; ++a)
  {
    const int s = ReinitStencil<D>::blockStride(a);
    g[a] = 0.5 * (block[c + s] - block[c - s]) * inverseSpacing[a];
  }
  double k = 0.0;
  for (int a = 0; a < D; ++a)
  {
    const int sa = ReinitStencil<D>::blockStride(a);
    const double second = (block[c + sa] - 2.0 * block[c] + block[c - sa]) * inverseSpacing[a] * inverseSpacing[a];
    for (int b = 0; b < D; ++b)
    {
      if (b == a)
      {
        continue;
      }
      k += second * g[b] * g[b];
      if (b > a)
      {
        const int sb = ReinitStencil<D>::blockStride(b);
        const double cross = block[c + sa + sb] - block[c + sa - sb] - block[c - sa + sb] + block[c - sa - sb];
        const double mixed = 0.25 * cross * inverseSpacing[a] * inverseSpacing[b];
        k -= 2.0 * g[a] * g[b] * mixed;
      }
    }
  }
  return k;
}

/// (1.45): the node of X belongs to R1 (kappa phi0 < 0, or kappa = 0 and phi0 < 0).
template <int D>
inline bool inFirstSet(const double* block, const double* inverseSpacing)
{
  const double phi = block[ReinitStencil<D>::Centre];
  const double kappa = curvatureNumerator<D>(block, inverseSpacing);
  return kappa * phi < 0.0 || (kappa == 0.0 && phi < 0.0);
}

/// Constrained value of a node of X (Hartmann et al., thesis 1.5.2): (1.37) on
/// R1; on R2 the least-squares value (1.44) from the neighbours across the
/// front that lie in the grid, or (1.37) when there is none. `i` is the node,
/// `block` its 3^D block of phi0, read through `stencil` (bound to phi0).
template <int D>
inline double constrainedDistance(const ReinitStencil<D>& stencil, const std::array<Index, D>& i, const double* block,
  const double* inverseSpacing, const double* spacing)
{
  constexpr int c = ReinitStencil<D>::Centre;
  const double phi = block[c];
  if (phi == 0.0 || inFirstSet<D>(block, inverseSpacing))
  {
    return interfaceDistance<D>(block, inverseSpacing, spacing);
  }
  const GridSpec<D>& g = stencil.spec();
  double neighbour[ReinitStencil<D>::BlockSize];
  double sum = 0.0;
  int count = 0; // M_{i,j} of (1.41)
  for (int a = 0; a < D; ++a)
  {
    const int s = ReinitStencil<D>::blockStride(a);
    for (int side = -1; side <= 1; side += 2)
    {
      const double other = block[c + side * s];
      if (!(phi * other < 0.0)) // N_{i,j}: strict sign change
      {
        continue;
      }
      std::array<Index, D> j = i;
      j[a] += side;
      if (j[a] < 0 || j[a] >= g.Dims[a])
      {
        if (g.Bounds[a] != Boundary::Periodic)
        {
          continue; // an extrapolated node has no block of its own
        }
        j[a] = (j[a] + g.Dims[a]) % g.Dims[a];
      }
      stencil.block(j, neighbour);
      sum += (phi / other) * interfaceDistance<D>(neighbour, inverseSpacing, spacing); // (1.40), (1.44)
      ++count;
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : interfaceDistance<D>(block, inverseSpacing, spacing);
}

} // namespace sltk
