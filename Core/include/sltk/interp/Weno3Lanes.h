// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Weno3Lanes.h
/// WENO3 (Weno3.h; thesis 2.3.4, (2.65)-(2.76)) at L points at once, one per
/// SIMD lane: the 2^(d-1) feet of a node of the SL step (4.22)/(4.24) each
/// have their own cell and local coordinates, but the dimension-split passes
/// are the same for all of them, so 21 one-dimensional reconstructions of four
/// lanes replace 84 of one (3D).
///
/// Each lane does the operations of weno3Interpolate1D (Weno3Kernel1D.h) in
/// the same order (Lanes.h), so a lane's value is that of
/// Weno3Interpolator::eval bit for bit; TestWeno3Lanes checks it.

#include "sltk/grid/GridField.h"
#include "sltk/interp/FeetLanes.h"
#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"

#include <array>
#include <cstring>

namespace sltk
{

namespace weno3lanes
{
using lanes::Lanes;

/// weno3Interpolate1D (2.69) lane by lane, its operations in its order, into
/// `out` (vectors go by reference: by value they would change the ABI).
template <int L>
SLTK_LANES_INLINE void interpolate1D(const Lanes<L>& fm1, const Lanes<L>& f0, const Lanes<L>& f1, const Lanes<L>& f2,
  const Lanes<L>& t, double eps, Lanes<L>& out)
{
  const Lanes<L> d2L = fm1 - 2.0 * f0 + f1;
  const Lanes<L> d2R = f0 - 2.0 * f1 + f2;
  const double eps2 = eps * eps;
  const Lanes<L> bL = d2L * d2L + eps2; // indicators (2.70), scaled as in weno3Weights1D
  const Lanes<L> bR = d2R * d2R + eps2;
  const Lanes<L> cL = (2.0 - t) * (1.0 / 3.0); // linear weights (2.76)
  const Lanes<L> cR = (1.0 + t) * (1.0 / 3.0);
  const Lanes<L> aL = cL * (bR * bR); // (2.67)
  const Lanes<L> aR = cR * (bL * bL);
  const Lanes<L> inv = 1.0 / (aL + aR);
  const Lanes<L> wL = aL * inv; // (2.68)
  const Lanes<L> wR = aR * inv;
  out = (1.0 - t) * f0 + t * f1 + 0.5 * t * (t - 1.0) * (wL * d2L + wR * d2R);
}

/// The dimension-split passes of Weno3Interpolator::eval on L stencils:
/// stencil[c] holds digit c (x fastest) of every lane's 4^D stencil, t[a]
/// every lane's local coordinate along axis a; the values end in stencil[0].
template <int D, int L>
SLTK_LANES_INLINE void evalStencils(Lanes<L>* stencil, const Lanes<L>* t, const double* eps)
{
  int n = ipow(4, D);
  for (int a = D - 1; a >= 0; --a) // the last axis first, x last (Weno3.h)
  {
    n /= 4;
    for (int c = 0; c < n; ++c)
    {
      const Lanes<L> fm1 = stencil[c];
      interpolate1D<L>(fm1, stencil[c + n], stencil[c + 2 * n], stencil[c + 3 * n], t[a], eps[a], stencil[c]);
    }
  }
}

} // namespace weno3lanes

/// WENO3 at 2^(D-1) located points (cell and local coordinates, sltk::locate)
/// of one field, one point per lane.
template <int D>
class Weno3Lanes : public FeetLanes<Weno3Lanes<D>, D>
{
public:
  using FeetLanes<Weno3Lanes<D>, D>::Count;
  static constexpr int StencilSize = ipow(4, D);

  explicit Weno3Lanes(const GridField<D, double>& field)
    : Field(&field)
    , Offset(stencilOffsets<D, 4>(field.strides(), -1)) // nodes -1..2 along each axis, as Weno3Interpolator
  {
    for (int a = 0; a < D; ++a)
    {
      const double dx = field.spec().Spacing[a];
      this->Eps[a] = dx * dx; // (2.67), as Weno3Interpolator
    }
  }

private:
  friend class FeetLanes<Weno3Lanes<D>, D>;
  using Vec = weno3lanes::Lanes<Count>;

  SLTK_LANES_INLINE void evalLanes(const std::array<CellLocation<D>, Count>& at, double* out) const
  {
    // Lanes are filled through arrays: a vector of a dependent size cannot be subscripted in a template.
    const double* corner[Count];
    double t[D][Count];
    for (int l = 0; l < Count; ++l)
    {
      corner[l] = this->Field->pointer(at[l].Cell);
      for (int a = 0; a < D; ++a)
      {
        t[a][l] = at[l].Local[a];
      }
    }
    alignas(sizeof(Vec)) double values[StencilSize][Count];
    for (int c = 0; c < StencilSize; ++c)
    {
      for (int l = 0; l < Count; ++l)
      {
        values[c][l] = corner[l][this->Offset[c]];
      }
    }
    // Read in place as vectors (the lane types may alias double).
    Vec* stencil = reinterpret_cast<Vec*>(&values[0][0]);
    Vec tv[D];
    std::memcpy(tv, t, sizeof(tv));
    weno3lanes::evalStencils<D, Count>(stencil, tv, this->Eps);
    std::memcpy(out, &stencil[0], sizeof(Vec));
  }

  const GridField<D, double>* Field;
  std::array<Index, StencilSize> Offset{};
  double Eps[D] = {};
};

} // namespace sltk
