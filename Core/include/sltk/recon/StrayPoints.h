// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file StrayPoints.h
/// Stray points far from the object, kept because the automatic cleaning was
/// turned off (CloudCleaning.h: --no-cleaning, or an explicit thinning),
/// stretch the unit box (4.5), inflate h_P (4.36) and so every grid, and pull
/// the front away from everything else. The failures they cause look like
/// others (the zero level set vanishes, the cloud looks flat against a huge
/// cell), and the fix is always the same: remove them. These are the words
/// for it, used where such a failure is reported.

#include "sltk/cloud/PointCloud.h"
#include "sltk/exec/Context.h"

#include <string>

namespace sltk
{

/// Advice to remove outliers when `cloud` has gross ones (GrossOutlierRatio),
/// naming how many and how far; empty when it has none.
template <int D>
std::string strayPointAdvice(const PointCloud<D>& cloud, const Context& ctx);

extern template std::string strayPointAdvice(const PointCloud<2>&, const Context&);
extern template std::string strayPointAdvice(const PointCloud<3>&, const Context&);

} // namespace sltk
