// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReconstructionInterpolator.h
/// The reconstruction's compile-time dispatch to its interpolator: the kinds
/// every solver offers (Interpolators.h), and the thesis's chapter 5
/// least-squares Q1 (5.5, LsqQ1.h), which only the reconstruction offers.

#include "sltk/interp/Interpolators.h"
#include "sltk/interp/LsqQ1.h"
#include "sltk/recon/ReconstructionOptions.h"

#include <utility>

namespace sltk
{

/// f(InterpolatorTag<I>{}) with I the reconstruction's interpolator in dimension D.
template <int D, class F>
decltype(auto) withReconstructionInterpolator(const ReconstructionOptions& options, F&& f)
{
  // The plan (ReconstructionPlan.h) has chosen an automatic interpolator before any run.
  const InterpolatorKind kind = options.Interpolator.value_or(InterpolatorKind::Weno3);
  if (kind == InterpolatorKind::LeastSquaresQ1)
  {
    return f(InterpolatorTag<LsqQ1Interpolator<D>>{});
  }
  return withInterpolator<D>(kind, std::forward<F>(f));
}

} // namespace sltk
