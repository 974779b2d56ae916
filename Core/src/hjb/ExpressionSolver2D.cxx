// SPDX-License-Identifier: BSD-3-Clause
// The 2D expression-defined HJB solvers (one translation unit per dimension
// so that the kernels of (3.7) compile in parallel).
#include "ExpressionSolverOf.h"

namespace sltk
{

template <>
Status makeExpressionSolverOf<2>(
  const HjbExpressionSpec& spec, const ExpressionSolverInput<2>& in, std::unique_ptr<HjbSolver>& solver)
{
  return makeExpressionSolverForDim<2>(spec, in, solver);
}

} // namespace sltk
