// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file EnergyFunctional.h
/// The energy E_p(phi) = (int |d|^p delta(phi) |grad phi| dx)^(1/p) of (4.5),
/// approximated on the cells where the front lies (thesis 4.4.3), assuming
/// |grad phi| = 1 there (phi reinitialised). phi and d are interpolated in
/// the cell by Q1 (4.28).
///
///  - 2D (4.29): in every cell where phi changes sign, the points where the
///    front cuts the cell edges come from linear interpolation of phi on the
///    edges; the integral of |d|^p on the segment joining them is the
///    trapezoidal rule. Saddle cells (four cuts) are split into two segments
///    by the sign of the Q1 value at the cell centre (the asymptotic decider
///    of marching squares).
///  - 3D (4.30): every cell is refined into R^3 subcells of size dx' = dx / R
///    (R = 5); the subcells whose Q1 value of phi at the centre satisfies
///    |I[Phi](x_i')| < h = sqrt(3)/2 dx' contribute |d(x_i')|^p times a
///    measure. The subcells are visited in every cell where the criterion can
///    hold (a sign change, or a corner with |phi| < h: Q1 is a convex
///    combination of the corners), not only in the sign-change cells.
///
/// Where the thesis is ambiguous: (4.30) weights each subcell by
/// (dx')^(n-1) = dx'^2, the codimension-one measure. Since the selected
/// subcells fill a shell of thickness 2h = sqrt(3) dx' around the surface,
/// that sum approximates sqrt(3) times the integral, for any orientation.
/// SubcellMeasure::Consistent (the default) divides by that thickness
/// (weight dx'^3 / (2h) = dx'^2 / sqrt(3)), which approximates the area;
/// SubcellMeasure::Thesis keeps the literal dx'^2. The two differ by the
/// constant factor sqrt(3)^(1/p) in E_p.

#include "sltk/exec/Communicator.h"
#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"
#include "sltk/levelset/NarrowBand.h"

namespace sltk
{

enum class SubcellMeasure : std::uint8_t
{
  Consistent = 0, ///< dx'^3 / (2h): the subcell sum approximates the surface integral
  Thesis = 1      ///< (dx')^(n-1) as printed in (4.30): sqrt(3) times larger
};

struct EnergyOptions
{
  double P = 2.0;       ///< p >= 1 of (4.1)
  double SecondP = 0.0; ///< a second exponent summed in the same traversal (0: none), e.g. E_2 for (4.33) when p = 1
  int Refinement = 5;   ///< R of (4.30) (3D only)
  SubcellMeasure Measure = SubcellMeasure::Consistent;
};

struct EnergyResult
{
  double Integral = 0.0;       ///< sum of |d|^p over the front (before the 1/p power)
  double Energy = 0.0;         ///< E_p = Integral^(1/p)
  double SecondIntegral = 0.0; ///< with EnergyOptions::SecondP = q: sum of |d|^q
  double SecondEnergy = 0.0;   ///< E_q
  Index FrontCells = 0;        ///< cells that contributed
};

/// E_p over every cell of the grid (phi and d on the same grid; ghosts unused).
template <int D>
Status energyFunctional(const GridField<D, double>& phi, const GridField<D, double>& distance, const Context& ctx,
  EnergyResult& result, const EnergyOptions& options = {});

/// E_p over the cells whose lowest corner is in `cells` (e.g. the band B^n of
/// (1.48): with gamma >= sqrt(D) dx and phi a distance it holds the lowest
/// corner of every cell where the front lies). O(band) work.
template <int D>
Status energyFunctional(const GridField<D, double>& phi, const GridField<D, double>& distance, const NodeList& cells,
  const Context& ctx, EnergyResult& result, const EnergyOptions& options = {});

/// E_p and E_q from the integrals: Integral^(1/p), SecondIntegral^(1/q).
void energiesFromIntegrals(EnergyResult& result, const EnergyOptions& options);

/// The energy of a slab decomposition (grid/Slabs.h): `local` holds this
/// rank's sums over the band cells of its owned rows (cells whose lowest
/// corner is in them); the integrals and front cells are added over the ranks
/// and E_p, E_q recomputed, alike on every rank. A collective call.
void reduceEnergy(EnergyResult& local, const EnergyOptions& options, const Communicator& comm);

extern template Status energyFunctional(
  const GridField<2, double>&, const GridField<2, double>&, const Context&, EnergyResult&, const EnergyOptions&);
extern template Status energyFunctional(
  const GridField<3, double>&, const GridField<3, double>&, const Context&, EnergyResult&, const EnergyOptions&);
extern template Status energyFunctional(const GridField<2, double>&, const GridField<2, double>&, const NodeList&,
  const Context&, EnergyResult&, const EnergyOptions&);
extern template Status energyFunctional(const GridField<3, double>&, const GridField<3, double>&, const NodeList&,
  const Context&, EnergyResult&, const EnergyOptions&);

} // namespace sltk
