// SPDX-License-Identifier: BSD-3-Clause
// The 1D expression-defined HJB solvers (one translation unit per dimension
// so that the kernels of (3.7) compile in parallel).
#include "ExpressionSolverOf.h"

namespace sltk
{

template <>
Status makeExpressionSolverOf<1>(
  const HjbExpressionSpec& spec, const ExpressionSolverInput<1>& in, std::unique_ptr<HjbSolver>& solver)
{
  return makeExpressionSolverForDim<1>(spec, in, solver);
}

} // namespace sltk
