// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Interpolators.h
/// Compile-time dispatch from a run-time InterpolatorKind (InterpolatorKind.h)
/// to its class: withInterpolator<D>(kind, f) calls f(InterpolatorTag<I>{})
/// with I the interpolator type for dimension D (the concept of
/// Interpolator.h), so a solver is instantiated once per kind in one place.

#include "sltk/interp/Cweno.h"
#include "sltk/interp/InterpolatorKind.h"
#include "sltk/interp/Q1.h"
#include "sltk/interp/Weno3.h"

#include <cassert>

namespace sltk
{

template <class Interp>
struct InterpolatorTag
{
  using type = Interp;
};

/// f(InterpolatorTag<I>{}) for the class I of `kind` in dimension D; every branch must return the same type.
/// The kinds every solver offers (offeredByHjb); the reconstruction dispatches its own
/// (ReconstructionInterpolator.h), and the HJB solver refuses it before (hjbInterpolatorOfCode).
template <int D, class F>
decltype(auto) withInterpolator(InterpolatorKind kind, F&& f)
{
  static_assert(interpolatorCount() == 5, "a new InterpolatorKind needs its case here");
  assert(offeredByHjb(kind));
  switch (kind)
  {
    case InterpolatorKind::Q1:
      return f(InterpolatorTag<Q1Interpolator<D>>{});
    case InterpolatorKind::Weno3:
      return f(InterpolatorTag<Weno3Interpolator<D>>{});
    case InterpolatorKind::Cweno:
      return f(InterpolatorTag<CwenoInterpolator<D>>{});
    case InterpolatorKind::CwenoZ:
    case InterpolatorKind::LeastSquaresQ1:
      break;
  }
  return f(InterpolatorTag<CwenoZInterpolator<D>>{});
}

} // namespace sltk
