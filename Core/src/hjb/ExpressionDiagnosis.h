// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ExpressionDiagnosis.h (private)
/// When a step of (3.7) on a formula-defined problem (ExpressionProblem.h)
/// produces NaN or Inf, the scheme only knows how many values went bad. This
/// finds the cause a user can act on: the first formula (f_D component, f_C,
/// v_0, g) that is not finite at a grid node, for a sample of the control set
/// A, and names it with the point.

#include "ExpressionSolverOf.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sltk
{

enum class FormulaScope
{
  StateFormulas, ///< v_0 and g only (functions of x, known before the first step)
  AllFormulas    ///< also f_D and f_C, at the sampled controls
};

/// The spacing along `axis`: (Upper - Lower) / (n - 1), / n on a periodic axis.
double axisSpacing(const HjbExpressionSpec& spec, int axis);

/// The grid of `spec` without its window (ExpressionProblem.h WindowFirst): a
/// distributed solve's slabs name a failing formula where the serial solve does.
HjbGrid wholeGrid(const HjbExpressionSpec& spec);

/// Controls at which to evaluate f_D and f_C without searching A: the corners
/// and the centre of a box, the centre and the poles of a ball or sphere, the
/// points of a finite set, a = 0 without controls (unused components 0).
std::vector<std::array<double, 3>> sampleControls(const HjbExpressionSpec& spec);

/// What to do about a formula that findNonFiniteFormula() names.
extern const char* const NonFiniteFix;

/// The first formula of `spec` (compiled in `compiled`) that is NaN or Inf at a
/// grid node, at time t, for the controls sampled from A (corners and centre of
/// a box, centre and poles of a ball or sphere, the points of a finite set),
/// as "the running cost f_C '1/x' is inf at t = 0, x = 0, y = -1, a1 = 1".
/// Empty when every formula is finite there.
std::string findNonFiniteFormula(const HjbExpressionSpec& spec, const CompiledHjbExpressions& compiled,
  const HjbGrid& grid, double t, FormulaScope scope);

/// Wraps the solver of a formula-defined problem: a step that fails with
/// non-finite values gets findNonFiniteFormula()'s answer (at the start and at
/// the end of the failed step) and the fix added to its message.
std::unique_ptr<HjbSolver> withNonFiniteDiagnosis(
  std::unique_ptr<HjbSolver> solver, const HjbExpressionSpec& spec, SharedHjbExpressions compiled);

} // namespace sltk
