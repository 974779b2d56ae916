// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file HjbError.h
/// The error measures of thesis 3.5: the L1 error dx^d sum_i |u_i - v(x_i)|
/// over all grid nodes (Documentation/Numerics.md) and the range of the solution (Table 3.9).

#include "sltk/grid/GridField.h"
#include "sltk/sl/LinearSLStep.h"

#include <cmath>
#include <limits>
#include <utility>

namespace sltk
{

/// dx^d sum_i |u_i - exact(x_i)|, exact(const std::array<double, D>&) -> double.
template <int D, class Exact>
double l1Error(const GridField<D, double>& u, Exact&& exact)
{
  const GridSpec<D>& spec = u.spec();
  double sum = 0.0;
  for (Index k = 0; k < spec.nodeCount(); ++k)
  {
    const auto i = u.nodeIndex(k);
    sum += std::fabs(u(i) - exact(nodePoint(spec, i)));
  }
  double cell = 1.0;
  for (int a = 0; a < D; ++a)
  {
    cell *= spec.Spacing[a];
  }
  return cell * sum;
}

/// (min, max) of the interior values.
template <int D>
std::pair<double, double> valueRange(const GridField<D, double>& u)
{
  std::pair<double, double> r{ std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
  for (Index k = 0; k < u.spec().nodeCount(); ++k)
  {
    const double v = u(u.nodeIndex(k));
    r.first = v < r.first ? v : r.first;
    r.second = v > r.second ? v : r.second;
  }
  return r;
}

} // namespace sltk
