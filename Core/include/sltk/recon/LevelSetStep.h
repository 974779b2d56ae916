// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LevelSetStep.h
/// One semi-Lagrangian step of the reconstruction model (4.9) on the narrow
/// band (thesis 4.3): in 2D (4.22) with the tangent (4.23), in 3D (4.24) with
/// the tangent frame (4.25), the scale factor with cut-off (4.32) and the
/// singular fallback (4.26):
///
///   phi_i^{n+1} = 2^{1-d} sum_j I[phi^n](x*_ij),
///   x*_ij = x_i + C_i dt grad d(x_i) + sqrt(2 C_i eta d(x_i) dt / p) sigma_i xi_j,
///   C_i = c(phi_i^n) (d(x_i) / E_p(phi^n))^(p-1).
///
/// Gradients are centred differences (thesis 4.3: "unless otherwise specified").
/// The step reads phi^n everywhere and writes phi^{n+1} on band nodes only:
/// new values are computed into a band-sized buffer, then stored, so no
/// full-grid copy is made.

#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/interp/CellCache.h"
#include "sltk/interp/Interpolator.h"
#include "sltk/interp/LsqQ1.h"
#include "sltk/interp/LsqQ1Lanes.h"
#include "sltk/interp/Weno3.h"
#include "sltk/interp/Weno3Lanes.h"
#include "sltk/levelset/CutOff.h"
#include "sltk/levelset/NarrowBand.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <vector>

namespace sltk
{

/// Parameters of one step of (4.9).
struct LevelSetStepParameters
{
  double P = 1.0;             ///< p of (4.9), Table 4.1
  double Eta = 0.05;          ///< eta of (4.9), Table 4.1
  double Energy = 1.0;        ///< E_p(phi^n), (4.29)/(4.30); only used when p != 1
  double TimeStep = 0.0;      ///< dt (4.36)
  BandWidths Widths;          ///< beta, gamma of the cut-off (4.4.6)
  double SingularD = 1e-3;    ///< D of the fallback threshold |grad phi| < D dt^alpha (4.26)
  double SingularAlpha = 1.0; ///< alpha of (4.26)
  /// Tunnel detection (4.5.6): where d(x_i) < 2 dx and |grad d(x_i)| < 0.5 (the bands
  /// of two close sheets of points merge over the kink of d), the velocity grad d
  /// is replaced by grad phi, so the front keeps its direction through the tunnel.
  /// Our addition: also d > 0.6 h_P. Between the samples of one sheet d has kinks
  /// too (d <= h_P / 2 there); without this bound the rule fires all along a
  /// sampled surface once dx < h_P (runs 2, 3) and the front stalls 0.013 off a
  /// slotted square's walls (Err_P 8.4e-3 instead of 1.8e-4, TestTunnelDetection).
  bool DetectTunnels = false;
  double TunnelDistance = 0.0;    ///< 2 dx
  double TunnelMinDistance = 0.0; ///< 0.6 h_P
  /// Beyond the thesis: band nodes with |phi| > FeetWithin take the step's first-order
  /// expansion (linearisedStep) instead of their feet; +infinity: the feet everywhere.
  /// The reconstruction sets beta (ReconstructionOptions::FeetWithinBeta).
  double FeetWithin = std::numeric_limits<double>::infinity();
};

/// The feet of a step on a slab window (grid/Slabs.h, Documentation/Distributed.md)
/// whose interpolation stencil leaves the window's rows: the step leaves them to
/// the caller, which has the ranks owning those rows interpolate them in one
/// batched exchange per step (thesis 4.4.1; recon/FarFeetExchange.h), so the
/// ghost rows need not be as wide as the longest foot.
template <int D>
struct FarFeet
{
  bool LowEdge = true;                     ///< the window's first row is the grid's (no rank below)
  bool HighEdge = true;                    ///< the window's last row is the grid's (no rank above)
  std::vector<Index> Positions;            ///< band positions with a far foot, ascending
  std::vector<double> Values;              ///< 2^(D-1) foot values per position, NaN where far
  std::vector<std::array<double, D>> Feet; ///< the far feet, by position then foot
  std::vector<Index> Slots;                ///< each far foot's place in Values
};

namespace detail
{

/// Centred-difference gradient of a field at node i (ghosts must be filled).
template <int D>
inline std::array<double, D> centredGradient(const GridField<D>& f, const double* p)
{
  std::array<double, D> g{};
  for (int a = 0; a < D; ++a)
  {
    const Index s = f.strides()[a];
    g[a] = (p[s] - p[-s]) / (2.0 * f.spec().Spacing[a]);
  }
  return g;
}

/// Orthonormal tangent vectors to the level set with normal direction g:
/// (4.23) in 2D; (4.25) in 3D, with the regularised choice when
/// phi_x^2 + phi_z^2 = 0.
inline void tangentFrame(const std::array<double, 2>& g, double norm, std::array<std::array<double, 2>, 1>& sigma)
{
  sigma[0] = { g[1] / norm, -g[0] / norm }; // (4.23)
}

inline void tangentFrame(const std::array<double, 3>& g, double norm, std::array<std::array<double, 3>, 2>& sigma)
{
  const double r = std::sqrt(g[0] * g[0] + g[2] * g[2]);
  if (r == 0.0)
  {
    sigma[0] = { 1.0, 0.0, 0.0 }; // regularised nu_1, nu_2 of (4.25)
    sigma[1] = { 0.0, 0.0, 1.0 };
    return;
  }
  sigma[0] = { -g[2] / r, 0.0, g[0] / r };                                       // nu_1 (4.25)
  sigma[1] = { -g[0] * g[1] / (r * norm), r / norm, -g[1] * g[2] / (r * norm) }; // nu_2 (4.25)
}

} // namespace detail

/// Whether the interpolation stencil (Interp::GhostWidth rows each side, one
/// more for rounding) of a foot at window row coordinate `row` lies in the
/// window's rows, or beyond an edge the whole grid shares (clipped there as on
/// one rank: GridSpec.h locate()).
template <class Interp, int D>
bool footInWindow(const GridSpec<D>& window, const FarFeet<D>& far, double row)
{
  const double cell = std::floor(row);
  return (far.LowEdge || cell >= Interp::GhostWidth) &&
    (far.HighEdge || cell + Interp::GhostWidth + 1 <= static_cast<double>(window.Dims[D - 1] - 1));
}

namespace detail
{
/// The scale factor with cut-off of (4.32), c(phi) (d / E_p)^(p-1); p = 2 (runs 2
/// and later of Table 4.1) without a call of pow (pow(x, 1) is x).
inline double stepScale(double phi, double d, const LevelSetStepParameters& par)
{
  const double ratio = d / par.Energy;
  return cutOff(phi, par.Widths) * (par.P == 1.0 ? 1.0 : (par.P == 2.0 ? ratio : std::pow(ratio, par.P - 1.0)));
}

/// The advection's direction at a band node: grad d (centred), or grad phi
/// through a tunnel (4.5.6: DetectTunnels, 0.6 h_P < d < 2 dx and |grad d| < 0.5).
template <int D, class Vector>
Vector advectionDirection(
  const GridField<D>& dist, const double* pd, const Vector& gphi, const LevelSetStepParameters& par)
{
  const Vector gd = centredGradient(dist, pd);
  const double d = *pd;
  if (par.DetectTunnels && d < par.TunnelDistance && d > par.TunnelMinDistance)
  {
    double gd2 = 0.0;
    for (int a = 0; a < D; ++a)
    {
      gd2 += gd[a] * gd[a];
    }
    if (gd2 < 0.25) // |grad d| < 0.5 (4.5.6)
    {
      return gphi;
    }
  }
  return gd;
}

/// The points of (4.22)/(4.24) around the advected point x0: x0 + spread sum_m xi_j,m sigma_m,
/// xi_j in {+-1}^(D-1).
template <int D, size_t Points>
void tangentFeet(const double* x0, double spread, const std::array<std::array<double, D>, D - 1>& sigma,
  std::array<std::array<double, D>, Points>& x)
{
  for (size_t j = 0; j < Points; ++j)
  {
    for (int a = 0; a < D; ++a)
    {
      x[j][a] = x0[a];
      for (int m = 0; m < D - 1; ++m)
      {
        const double xi = ((j >> m) & 1) ? 1.0 : -1.0;
        x[j][a] += spread * sigma[m][a] * xi;
      }
    }
  }
}

/// The step (4.22)/(4.24) to first order in its displacements, phi + c dt grad phi . v
/// (v = grad d or, through a tunnel, grad phi; the tangent spread averages out to first
/// order): for the band's nodes beyond beta, whose values the reinitialisation (1.38)-(1.45)
/// rebuilds from the front, so that only its starting value is taken from here.
template <int D, class Vector>
double linearisedStep(double phi, double scale, double timeStep, const Vector& gphi, const Vector& v)
{
  double slope = 0.0;
  for (int a = 0; a < D; ++a)
  {
    slope += gphi[a] * v[a];
  }
  return phi + scale * timeStep * slope;
}

/// The far feet one chunk of the band found (levelSetStepValues).
template <int D>
struct ChunkFeet
{
  std::vector<Index> Positions;
  std::vector<double> Values;
  std::vector<std::array<double, D>> Feet;
  std::vector<Index> Slots;
};

/// The chunks' far feet joined in chunk order into `far` (the same lists for any thread count).
template <int D>
void joinFarFeet(std::map<Index, ChunkFeet<D>>& farByChunk, FarFeet<D>& far)
{
  far.Positions.clear();
  far.Values.clear();
  far.Feet.clear();
  far.Slots.clear();
  for (auto& [first, chunk] : farByChunk)
  {
    const Index shift = static_cast<Index>(far.Values.size());
    for (const Index slot : chunk.Slots)
    {
      far.Slots.push_back(shift + slot);
    }
    far.Positions.insert(far.Positions.end(), chunk.Positions.begin(), chunk.Positions.end());
    far.Values.insert(far.Values.end(), chunk.Values.begin(), chunk.Values.end());
    far.Feet.insert(far.Feet.end(), chunk.Feet.begin(), chunk.Feet.end());
  }
}
} // namespace detail

namespace detail
{
/// Whether every foot of a node, `x`, is finite and, on a slab window (`far`),
/// inside it (StepLanes, tryEvalInCache).
template <class Interp, int D, size_t P>
bool feetInWindow(const GridSpec<D>& spec, const FarFeet<D>* far, const std::array<std::array<double, D>, P>& x)
{
  for (size_t j = 0; j < P; ++j)
  {
    for (int a = 0; a < D; ++a)
    {
      if (!std::isfinite(x[j][a]))
      {
        return false;
      }
    }
    if (far && !footInWindow<Interp>(spec, *far, spec.indexCoordinate(D - 1, x[j][D - 1])))
    {
      return false;
    }
  }
  return true;
}

/// The feet of a node interpolated together where the interpolator can
/// (WENO3: Weno3Lanes.h; the least-squares Q1: LsqQ1Lanes.h, straight from phi;
/// the values of the interpolator bit for bit): every foot finite and, on a slab
/// window, inside it. tryEval() returns false otherwise, and for the other
/// interpolators; the step then tries the cell cache's lanes (tryEvalInCache:
/// CWENO), else takes the feet one by one.
template <class Interp, int D>
struct StepLanes
{
  explicit StepLanes(const GridField<D>&) {}
  template <size_t P>
  bool tryEval(const GridSpec<D>&, const FarFeet<D>*, const std::array<std::array<double, D>, P>&, double*)
  {
    return false;
  }
};

/// The feet of a node through a cache that builds the cells they miss together,
/// in SIMD lanes (CWENO: CellCache::evaluate(), the values and builds of one
/// foot at a time): every foot finite and, on a slab window, inside it; false
/// otherwise, and for the caches of the other interpolators.
template <class Interp, int D, class Cache, size_t P>
bool tryEvalInCache(Cache& cache, const GridSpec<D>& spec, const FarFeet<D>* far,
  const std::array<std::array<double, D>, P>& x, double* values)
{
  if constexpr (!Cache::StoresPolynomials)
  {
    return false;
  }
  else
  {
    static_assert(P <= Cache::PointLanes, "the feet of a node are evaluated together");
    if (!feetInWindow<Interp, D>(spec, far, x))
    {
      return false;
    }
    const double* points[P];
    for (size_t j = 0; j < P; ++j)
    {
      points[j] = x[j].data();
    }
    cache.evaluate(static_cast<int>(P), points, values);
    return true;
  }
}

/// The feet of a node in the lanes of `LanesOfFeet` (Weno3Lanes, LsqQ1Lanes).
template <class Interp, int D, class LanesOfFeet>
struct StepInLanes
{
  explicit StepInLanes(const GridField<D>& phi)
    : Lanes(phi)
  {
  }

  template <size_t P>
  bool tryEval(
    const GridSpec<D>& spec, const FarFeet<D>* far, const std::array<std::array<double, D>, P>& x, double* values)
  {
    static_assert(P == LanesOfFeet::Count, "one lane per foot");
    if (!feetInWindow<Interp, D>(spec, far, x))
    {
      return false;
    }
    std::array<CellLocation<D>, P> at;
    for (size_t j = 0; j < P; ++j)
    {
      at[j] = locate(spec, x[j].data());
    }
    this->Lanes.eval(at, values);
    return true;
  }

  LanesOfFeet Lanes;
};

template <int D>
struct StepLanes<Weno3Interpolator<D>, D> : StepInLanes<Weno3Interpolator<D>, D, Weno3Lanes<D>>
{
  using StepInLanes<Weno3Interpolator<D>, D, Weno3Lanes<D>>::StepInLanes;
};

/// The least-squares Q1 reads the 3^D nodes around each foot's nearest node
/// only, where its cache (StencilCache) would read the 4^D around the cell.
template <int D>
struct StepLanes<LsqQ1Interpolator<D>, D> : StepInLanes<LsqQ1Interpolator<D>, D, LsqQ1Lanes<D>>
{
  using StepInLanes<LsqQ1Interpolator<D>, D, LsqQ1Lanes<D>>::StepInLanes;
};
} // namespace detail

/// The new values of one step on `band` (ascending linear node indices, no
/// ghosts) into `values` (band order), phi unchanged. phi must carry
/// Interp::GhostWidth ghost layers, dist at least one; the ghosts of phi are
/// refilled here. With `far` (a slab window), the feet whose stencil leaves
/// the window are listed there instead of interpolated and their nodes'
/// values are left for finishFarNodes(). Returns numericalFailure when a new
/// value is not finite.
template <class Interp, int D>
Status levelSetStepValues(const Context& ctx, GridField<D>& phi, const GridField<D>& dist, const NodeList& band,
  const LevelSetStepParameters& par, std::vector<double>& values, FarFeet<D>* far = nullptr)
{
  static_assert(Interp::Dim == D, "interpolator dimension mismatch");
  if (phi.ghost() < Interp::GhostWidth || dist.ghost() < 1)
  {
    return Status::invalidArgument("levelSetStep: phi needs the interpolator's ghost layers and dist one");
  }
  if (!(par.TimeStep > 0.0) || !(par.P >= 1.0) || !(par.Eta >= 0.0) || !(par.Energy > 0.0))
  {
    return Status::invalidArgument("levelSetStep: need dt > 0, p >= 1, eta >= 0 and E_p > 0");
  }
  phi.fillGhosts(ctx);
  const GridSpec<D>& spec = phi.spec();
  const Index count = static_cast<Index>(band.size());
  values.resize(band.size());
  constexpr int Points = 1 << (D - 1); // 2 in 2D (4.22), 4 in 3D (4.24)
  const double singular = par.SingularD * std::pow(par.TimeStep, par.SingularAlpha);
  // Far feet of each chunk, joined in chunk order after the loop (the same lists for any thread count).
  using ChunkFeet = detail::ChunkFeet<D>;
  std::map<Index, ChunkFeet> farByChunk;
  std::mutex farMutex;

  const Interp prototype(phi);
  const double bad = ctx.parallelSum(0, count,
    [&](Index b, Index e)
    {
      // CWENO: the polynomial of a cell serves all the feet that fall in it (CellCache.h);
      // Q1/WENO3 prepare cheaply, one cell is enough. Results do not depend on the size.
      CellCache<Interp, detail::IsCwenoInterpolator<Interp>::value ? 1024 : 1> interpolateAt(prototype, phi);
      detail::StepLanes<Interp, D> lanes(phi); // WENO3, least-squares Q1: all the feet of a node at once
      ChunkFeet chunkFar;
      double failures = 0.0;
      for (Index k = b; k < e; ++k)
      {
        const auto i = phi.nodeIndex(band[static_cast<size_t>(k)]);
        const double* pp = phi.pointer(i);
        const double* pd = dist.pointer(i);
        const auto gphi = detail::centredGradient(phi, pp);
        double norm2 = 0.0;
        for (int a = 0; a < D; ++a)
        {
          norm2 += gphi[a] * gphi[a];
        }
        const double norm = std::sqrt(norm2);
        double value = 0.0;
        if (norm < singular)
        {
          // (4.26): mean of the first neighbours (interpolation at nodes returns the node values).
          for (int a = 0; a < D; ++a)
          {
            const Index s = phi.strides()[a];
            value += pp[s] + pp[-s];
          }
          value /= 2.0 * D;
        }
        else
        {
          const double d = *pd;
          // scale factor with cut-off (4.32)
          const double scale = detail::stepScale(*pp, d, par);
          const auto gd = detail::advectionDirection(dist, pd, gphi, par);
          if (std::fabs(*pp) > par.FeetWithin)
          {
            value = detail::linearisedStep<D>(*pp, scale, par.TimeStep, gphi, gd);
            failures += std::isfinite(value) ? 0.0 : 1.0;
            values[static_cast<size_t>(k)] = value;
            continue;
          }
          std::array<std::array<double, D>, D - 1> sigma;
          detail::tangentFrame(gphi, norm, sigma);
          const double spread = std::sqrt(2.0 * scale * par.Eta * d * par.TimeStep / par.P);
          double x0[D];
          for (int a = 0; a < D; ++a)
          {
            x0[a] = spec.coordinate(a, i[a]) + scale * par.TimeStep * gd[a]; // foot of the advection
          }
          std::array<std::array<double, D>, Points> x;
          detail::tangentFeet<D>(x0, spread, sigma, x);
          std::array<double, Points> feet;
          bool farNode = false;
          if (!lanes.tryEval(spec, far, x, feet.data()) &&
            !detail::tryEvalInCache<Interp, D>(interpolateAt, spec, far, x, feet.data()))
          {
            for (int j = 0; j < Points; ++j)
            {
              bool finite = true;
              for (int a = 0; a < D; ++a)
              {
                finite = finite && std::isfinite(x[j][a]);
              }
              if (!finite) // a non-finite energy or distance: no cell to interpolate in
              {
                feet[j] = std::numeric_limits<double>::quiet_NaN();
                continue;
              }
              if (far && !footInWindow<Interp>(spec, *far, spec.indexCoordinate(D - 1, x[j][D - 1])))
              {
                feet[j] = std::numeric_limits<double>::quiet_NaN();
                chunkFar.Feet.push_back(x[j]);
                chunkFar.Slots.push_back(static_cast<Index>(chunkFar.Values.size()) + j);
                farNode = true;
                continue;
              }
              feet[j] = interpolateAt(x[j].data());
            }
          }
          if (farNode)
          {
            chunkFar.Positions.push_back(k);
            chunkFar.Values.insert(chunkFar.Values.end(), feet.begin(), feet.end());
            values[static_cast<size_t>(k)] = 0.0; // finishFarNodes()
            continue;
          }
          for (int j = 0; j < Points; ++j)
          {
            value += feet[j];
          }
          value /= Points;
        }
        failures += std::isfinite(value) ? 0.0 : 1.0;
        values[static_cast<size_t>(k)] = value;
      }
      if (!chunkFar.Positions.empty())
      {
        const std::lock_guard<std::mutex> lock(farMutex);
        farByChunk.emplace(b, std::move(chunkFar));
      }
      return failures;
    });
  if (bad > 0.0)
  {
    return Status::numericalFailure("the level-set step produced " + std::to_string(static_cast<long long>(bad)) +
      " non-finite values: check the distance field and the energy");
  }
  if (far)
  {
    detail::joinFarFeet(farByChunk, *far);
  }
  return Status::ok();
}

/// After the far feet's values were filled in (far.Values, no NaN left where
/// a foot was far): the new values of their nodes, summed over the feet in the
/// order the one-rank step sums them.
template <int D>
Status finishFarNodes(const FarFeet<D>& far, std::vector<double>& values)
{
  constexpr int Points = 1 << (D - 1);
  Index bad = 0;
  for (size_t n = 0; n < far.Positions.size(); ++n)
  {
    double value = 0.0;
    for (int j = 0; j < Points; ++j)
    {
      value += far.Values[n * Points + static_cast<size_t>(j)];
    }
    value /= Points;
    bad += std::isfinite(value) ? 0 : 1;
    values[static_cast<size_t>(far.Positions[n])] = value;
  }
  if (bad > 0)
  {
    return Status::numericalFailure("the level-set step produced " + std::to_string(static_cast<long long>(bad)) +
      " non-finite values at feet another rank interpolated: check the distance field and the energy");
  }
  return Status::ok();
}

/// Stores the new values of a step (levelSetStepValues) on the band; `change`
/// receives sum over the band of |phi^{n+1} - phi^n| (numerator of eps_1
/// (4.34)) when non-null.
template <int D>
void storeLevelSetStep(const Context& ctx, GridField<D>& phi, const NodeList& band, const std::vector<double>& values,
  double* change = nullptr)
{
  const double moved = ctx.parallelSum(0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      double sum = 0.0;
      for (Index k = b; k < e; ++k)
      {
        double& target = phi(phi.nodeIndex(band[static_cast<size_t>(k)]));
        sum += std::fabs(values[static_cast<size_t>(k)] - target);
        target = values[static_cast<size_t>(k)];
      }
      return sum;
    });
  if (change)
  {
    *change = moved;
  }
}

/// Advances phi by one step on `band` (levelSetStepValues, then the store: the
/// reads of phi^n are complete before any band value changes, so no
/// full-grid copy is made). `change` as storeLevelSetStep.
template <class Interp, int D>
Status levelSetStep(const Context& ctx, GridField<D>& phi, const GridField<D>& dist, const NodeList& band,
  const LevelSetStepParameters& par, std::vector<double>& scratch, double* change = nullptr)
{
  SLTK_RETURN_IF_ERROR((levelSetStepValues<Interp, D>(ctx, phi, dist, band, par, scratch)));
  storeLevelSetStep(ctx, phi, band, scratch, change);
  return Status::ok();
}

} // namespace sltk
