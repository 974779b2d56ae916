// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ReconstructionInterpolator.h
/// The reconstruction's compile-time dispatch to its interpolator: the kind
/// the options name (Interpolators.h), or the thesis's chapter 5 least squares
/// Q1 (5.5, LsqQ1.h) when ReconstructionOptions::LeastSquaresQ1 asks for the
/// side-by-side with the thesis's adaptive scheme. Only the reconstruction
/// offers the latter (the HJB solver does not), so it is not an
/// InterpolatorKind.

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
  if (options.LeastSquaresQ1)
  {
    return f(InterpolatorTag<LsqQ1Interpolator<D>>{});
  }
  return withInterpolator<D>(options.Interpolator, std::forward<F>(f));
}

} // namespace sltk
