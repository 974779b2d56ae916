// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file LeastSquaresQ1.h
/// The least-squares Q1 polynomial of a leaf (thesis 5.2.1, (5.5)): basis
/// {1, x'_1, x'_2, x'_1 x'_2} in 2D (its trilinear analogue in 3D) in
/// x' = (x - x_i) / Delta x_i, fitted to the values at the centres of the
/// leaf's face, edge and corner neighbours, with the constraint
/// p_i(x_i) = phi_i (c_0 = phi_i: the reduced system of 2^D - 1 unknowns).
/// The minimum-norm solution where the neighbours do not determine every
/// coefficient (nothing here relies on 2:1 balance to exclude it).

#include "CellTree.h"

#include "sltk/exec/Context.h"

#include <vector>

namespace sltk
{
namespace p4est
{

/// (5.5) for leaf i of `graph` on `values` (one per leaf).
template <int D>
CellPolynomial<D> fitLeastSquaresQ1(const LeafGraph<D>& graph, const std::vector<double>& values, int i);

/// (5.5) for every leaf of this rank (`values` given at its ghosts too).
template <int D>
void fitLeastSquaresQ1(const LeafGraph<D>& graph, const std::vector<double>& values, const Context& ctx,
  std::vector<CellPolynomial<D>>& polynomials);

} // namespace p4est
} // namespace sltk
