// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file ClosestPointReinit.h
/// The reinitialisation of the cell-centred scheme (thesis 5.2.4), after
/// Saye's high-order closest points:
///  1. T_0: the leaves with a neighbour of the other sign (phi_i phi_j <= 0);
///  2. seeds: the centres of the 2^D subcells of every leaf of T_0 projected
///     onto the zero level set of the leaf's polynomial (Newton);
///  3. every leaf of T_0 takes the nearest seed of the leaves within two
///     neighbour steps (its own, its neighbours', theirs) as the first guess
///     of Newton's method for its closest point on the zero level set of the
///     seed's leaf's polynomial (the Lagrangian system of Saye's method),
///     and phi_i = sign(phi~_i) |x_i - x*|, fixed. Saye takes the nearest of
///     all the seeds (a k-d tree). One neighbour step is not enough: a seed
///     lies up to a leaf from its leaf's centre, and with one step the
///     thesis's circle gave Err_P 1.87e-3 instead of 1.10e-3. Two steps gave
///     the k-d tree's results to every digit on the circle and the square,
///     and two steps are what a rank holds of the other ranks' leaves (the
///     ghost layer expanded once), so the result is the same on any number
///     of ranks. A leaf of T_0 with no seed there is left to the propagation;
///  4. the other leaves by the propagation (5.8)-(5.9) from T_0 with their
///     sign kept, up to gamma; phi is cut to [-gamma, gamma] (1.49).

#include "CellTree.h"

#include "sltk/exec/Context.h"

#include <vector>

namespace sltk
{
namespace p4est
{

struct ClosestPointReport
{
  int FrontLeaves = 0;   ///< |T_0|
  int Seeds = 0;         ///< projected subcell centres
  int SeedFallbacks = 0; ///< leaves of T_0 whose Newton iteration failed: the seed itself
  int Unseeded = 0;      ///< leaves of T_0 with no seed in their neighbourhood: left to the propagation
};

/// phi~ in `phi` (one per leaf, with its least-squares polynomials, both
/// given at the ghosts too) becomes the reinitialised phi at this rank's
/// leaves. `tree` (the tree of `graph`) is needed on several ranks, and then
/// the call is collective.
template <int D>
ClosestPointReport reinitialiseByClosestPoints(const LeafGraph<D>& graph,
  const std::vector<CellPolynomial<D>>& polynomials, double gamma, const Context& ctx, std::vector<double>& phi,
  const CellTree<D>* tree = nullptr);

} // namespace p4est
} // namespace sltk
