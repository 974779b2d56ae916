// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ExpressionProblem.h
/// An HJB problem (3.1)-(3.4) with state constraints (3.39) written as
/// formulas (Expression.h), as users of the VTK filter and of `sltk hjb` give it:
///
///   v_t + H(t, x, Dv) = 0,   H(t, x, p) = max_{a in A} { -f_D(t, x, a) . p - f_C(t, x, a) },   v(0, x) = v_0(x)
///
/// (thesis (3.1)-(3.3)); the scheme (3.7) follows y' = f_D backwards in time
/// from each node. Variables: x, y, z (as many as the dimension), t, and
/// a1, a2, a3 (as many as the control dimension). f_D components and f_C may
/// use all of them; v_0 and g use x, y, z; the exact solution and the
/// closed-form argmin (optional) x, y, z and t.
/// Example, thesis Test 4 (3.37): f_D = (-a1, -a2), f_C = (a1^2 + a2^2)/2,
/// A = disc of radius 2.2, v_0 = max(1 - x^2 - y^2, 0).

#include "sltk/grid/GridSpec.h"
#include "sltk/hjb/ControlSet.h"
#include "sltk/hjb/Minimizer.h"
#include "sltk/interp/InterpolatorKind.h"
#include "sltk/sl/ButcherTableau.h"

#include <array>
#include <string>
#include <vector>

namespace sltk
{

struct HjbExpressionSpec
{
  int Dimension = 2;                               ///< 1, 2 or 3
  std::array<Index, 3> Nodes{ 81, 81, 81 };        ///< per axis (periodic axes: distinct nodes)
  std::array<double, 3> Lower{ -1.0, -1.0, -1.0 }; ///< domain [Lower, Upper] per axis
  std::array<double, 3> Upper{ 1.0, 1.0, 1.0 };
  std::array<Boundary, 3> Bounds{ Boundary::Extrapolate, Boundary::Extrapolate, Boundary::Extrapolate };
  /// A window of that grid (a slab of a distributed solve, DistributedHjbSolver.h):
  /// nodes [WindowFirst, WindowFirst + WindowNodes) per axis, at the whole grid's
  /// coordinates bitwise (GridSpec::Offset); WindowNodes 0: the whole axis.
  /// InitialValues then hold the window's nodes.
  std::array<Index, 3> WindowFirst{ 0, 0, 0 };
  std::array<Index, 3> WindowNodes{ 0, 0, 0 };

  std::array<std::string, 3> Dynamics; ///< f_D components ("" on unused axes)
  std::string Cost;                    ///< f_C; empty: 0 (no quadrature)
  std::string Initial;                 ///< v_0; ignored when InitialValues is given
  std::vector<double> InitialValues;   ///< v_0 at the nodes, x fastest (e.g. from an image)
  std::string Obstacle;                ///< g of (3.39); empty: unconstrained
  std::string Exact;                   ///< exact v(t, x); empty: unknown
  /// Closed-form argmin a*(t, x) of (3.7), one formula per control component
  /// (in x, y, z, t); all empty: the minimiser searches A. Projected onto A.
  std::array<std::string, 3> Argmin;
  bool ReachableSet = false; ///< keep (3.40); also when an obstacle is given

  ControlKind Controls = ControlKind::None;
  int ControlDimension = 1;                               ///< m of A in R^m (1-3)
  std::array<double, 3> ControlLower{ -1.0, -1.0, -1.0 }; ///< Box
  std::array<double, 3> ControlUpper{ 1.0, 1.0, 1.0 };
  std::array<double, 3> ControlCenter{ 0.0, 0.0, 0.0 }; ///< Ball, Sphere
  double ControlRadius = 1.0;
  std::vector<std::array<double, 3>> ControlPoints; ///< Finite

  RkOrder Order = RkOrder::Kutta3; ///< feet (3.8) and quadrature (3.9)
  double FinalTime = 1.0;
  double CourantNumber = 1.0; ///< dt = lambda min_j dx_j
  MinimizerOptions Minimizer;
  InterpolatorKind Interpolator = InterpolatorKind::CwenoZ;
};

} // namespace sltk
