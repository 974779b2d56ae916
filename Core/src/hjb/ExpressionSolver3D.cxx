// SPDX-License-Identifier: BSD-3-Clause
// The 3D expression-defined HJB solvers (one translation unit per dimension
// so that the kernels of (3.7) compile in parallel).
#include "ExpressionSolverOf.h"

namespace sltk
{

template <>
Status makeExpressionSolverOf<3>(
  const HjbExpressionSpec& spec, const ExpressionSolverInput<3>& in, std::unique_ptr<HjbSolver>& solver)
{
  return makeExpressionSolverForDim<3>(spec, in, solver);
}

} // namespace sltk
