// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file CellEnergy.h
/// The energy E_p (4.5) and the cloud error Err_P (4.35) on the cell-centred
/// tree. The thesis's chapter 5 keeps chapter 4's stopping rule without
/// saying how E_p is integrated on the tree; here chapter 4's quadrature is
/// applied leaf by leaf to the leaf's own polynomial (the "disconnected"
/// zero level set the thesis draws, 5.3.1: each leaf holds its own piece),
/// with d from the leaf's polynomial of d:
///  - 2D (4.29): the front in the leaf's square is cut on its edges by linear
///    interpolation of the polynomial's corner values (saddles split by the
///    sign at the centre, marching squares' asymptotic decider); |d|^p is
///    integrated along each segment by the trapezoidal rule;
///  - 3D (4.30): the leaf is divided into subcells of edge h' = Delta x_min / R
///    (R = 5; the finest leaves' subcells, in every leaf, so that the shell
///    below is the same everywhere); those whose centre has
///    |p| < sqrt(3)/2 h' contribute |d|^p h'^2 / sqrt(3), the uniform
///    version's consistent measure (EnergyFunctional.h,
///    SubcellMeasure::Consistent).

#include "CellTree.h"

#include "sltk/core/Index.h"
#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"

#include <vector>

namespace sltk
{
namespace p4est
{

struct CellEnergy
{
  double Integral = 0.0;       ///< sum of |d|^p over the front
  double SecondIntegral = 0.0; ///< sum of |d|^q
  Index FrontLeaves = 0;       ///< leaves holding a piece of the front
};

/// The integrals of |d|^p and |d|^q over every leaf's piece of the front,
/// over all ranks of `comm` (collective), added in the global Morton order;
/// `finest` is Delta x_min.
template <int D>
CellEnergy cellEnergy(const LeafGraph<D>& graph, const std::vector<CellPolynomial<D>>& phi,
  const std::vector<CellPolynomial<D>>& distance, double finest, double p, double q, const Context& ctx,
  const Communicator& comm);

/// Err_P (4.35) and the far points of the cell-centred tree.
struct CellCloudErrors
{
  double Mean = 0.0;        ///< Err_P: the mean of |p_k(Q)|
  double FarFraction = 0.0; ///< the share of the points with |p_k(Q)| > far
};

/// Err_P (4.35): the mean of |p_k(Q)| over the points Q, k the leaf holding Q
/// (CellTree::locate; the leaves below `owned` are this rank's), and the
/// share of the points farther than `far`, over all ranks of `comm`
/// (collective), added in the points' order.
template <int D>
CellCloudErrors cellCloudErrors(const std::vector<std::array<double, D>>& points, const std::vector<int>& leafOfPoint,
  const std::vector<CellPolynomial<D>>& phi, int owned, double far, const Communicator& comm);

} // namespace p4est
} // namespace sltk
