// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
/// \file PointValues.h
/// The interpolation at the feet of the SL step (thesis (5.4), 5.2.1
/// "Localizing the feet"): the value at each point of the least-squares
/// polynomial of the leaf that holds it. A point in one of this rank's
/// leaves is evaluated here; the others go to the rank that owns their leaf
/// (CellTree::owners, p4est's partition), which evaluates them and answers,
/// all in one exchange each way per call.

#include "CellTree.h"

#include <vector>

namespace sltk
{
namespace p4est
{

/// values[k] = p_i(points[k]), i the leaf holding points[k] (CellTree::locate's
/// convention outside the cube), from `polynomials` of this rank's leaves
/// (indexed as `graph`, the tree's last leaves()). Collective; fails on
/// every rank (numericalFailure) when a rank is sent a point it does not hold.
template <int D>
Status valuesAtPoints(const CellTree<D>& tree, const LeafGraph<D>& graph,
  const std::vector<CellPolynomial<D>>& polynomials, const std::vector<std::array<double, D>>& points,
  std::vector<double>& values);

} // namespace p4est
} // namespace sltk
