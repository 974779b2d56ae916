// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file FastSweeping.h
/// Zhao's fast sweeping method (thesis ref. [121], used in 4.4.2 and 4.4.4)
/// for the Eikonal equation |grad u| = 1 on a uniform grid: Gauss-Seidel
/// sweeps in the 2^D alternating orders with the upwind Godunov update
///   sum_a ((u - a_a)^+ / dx_a)^2 = 1,  a_a = min of the two neighbours along a,
/// keeping u_i = min(u_i, update). Frozen nodes (the data) never change;
/// the others must start at a large value (e.g. +infinity).
///
/// The sweeps are sequential (Gauss-Seidel order is what makes them converge
/// in a few cycles), so the result does not depend on the executor. With
/// locking (Bak, McLaughlin and Renzi 2010) a node is recomputed only when a
/// neighbour changed since its last update: same result as the plain method,
/// less work after the first cycle. Work O(nodes) per sweep at most; memory:
/// one byte per node for the locks (allocated once per call). Values on the
/// ghost layers are neither used nor touched: call fillGhosts() afterwards if
/// an interpolator needs them.

#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"

#include <cstdint>
#include <vector>

namespace sltk
{

struct FastSweepingOptions
{
  int MaxCycles = 50; ///< a cycle is 2^D sweeps; stop after this many
  /// Stop when no value decreased by more than Tolerance * min dx in a cycle
  /// (1e-6: far below the O(dx) error of the scheme; 0: until nothing changes).
  double Tolerance = 1e-6;
};

struct FastSweepingReport
{
  int Cycles = 0;          ///< cycles run (the last one is the one that changed nothing)
  double LastChange = 0.0; ///< largest change in the last cycle
  bool Converged = false;
};

/// The Godunov upwind solution of (4.4.2)'s Eikonal at one node from the
/// smallest neighbour value per axis `a` (infinity: no information along
/// that axis) and the spacings `h`.
double godunovEikonal(const double* a, const double* h, int dims);

/// godunovEikonal() with the spacing h on every axis, bit for bit when no
/// value of `a` is NaN, by a shorter chain of operations (the sweeps' update
/// on the reconstruction's cubic cells).
double godunovEikonalUniform(const double* a, double h, int dims);

/// Sweeps u (interior nodes only). `frozen` has one entry per interior node
/// in x-fastest order; nonzero entries are fixed data.
template <int D>
Status fastSweep(GridField<D, double>& u, const std::vector<std::uint8_t>& frozen, const Context& ctx,
  const FastSweepingOptions& options = {}, FastSweepingReport* report = nullptr);

extern template Status fastSweep(GridField<2, double>&, const std::vector<std::uint8_t>&, const Context&,
  const FastSweepingOptions&, FastSweepingReport*);
extern template Status fastSweep(GridField<3, double>&, const std::vector<std::uint8_t>&, const Context&,
  const FastSweepingOptions&, FastSweepingReport*);

} // namespace sltk
