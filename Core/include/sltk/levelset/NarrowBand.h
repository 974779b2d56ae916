// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file NarrowBand.h
/// Narrow bands as lists of active nodes (thesis 1.6, 4.4.6): the update band
/// B^n = {|phi^n| < gamma} (1.48), the reinitialisation band of (1.52)-(1.53)
/// (B^n dilated by k cells) and the cutting (1.49).
///
/// A band is the ascending list of the linear indices (x fastest, no ghosts,
/// as GridField::nodeIndex) of its nodes. Only the first band needs a scan of
/// the whole grid (collectBand, O(nodes) work, parallel); afterwards
/// B^{n+1} = {x in Bbar^{n+1} : |phi^{n+1}| < gamma} is filtered from the
/// reinitialisation band (filterBand, O(band) work), which holds it when phi
/// is cut (1.49) outside the band. Memory: 8 bytes per band node. An output
/// list is written in place, its capacity reused (a run keeps its lists from
/// iteration to iteration); it may also be an input of the same call.

#include "sltk/exec/Context.h"
#include "sltk/grid/GridField.h"

#include <cstdint>
#include <vector>

namespace sltk
{

using NodeList = std::vector<Index>;

/// (1.48)/(1.50): all nodes with |phi| < gamma, by a full scan.
template <int D>
void collectBand(const GridField<D, double>& phi, double gamma, const Context& ctx, NodeList& band);

/// (1.54): the nodes of `candidates` with |phi| < gamma (order kept).
template <int D>
void filterBand(
  const GridField<D, double>& phi, const NodeList& candidates, double gamma, const Context& ctx, NodeList& band);

/// (1.52)-(1.53): the nodes within k cells (Euclidean, in index units:
/// sum_a o_a^2 <= k^2) of a band node, the band included, ascending; k = 1
/// adds the 2D face neighbours. `more` (optional, any order) dilates with the
/// band, e.g. a slab's ghost-row band (its nodes may repeat the band's).
/// Indices outside the grid are ignored. Work O(band * k^D) plus one pass over
/// the grid's x lines, on the context's threads, x line by x line (the same list
/// on any thread count).
template <int D>
void dilateBand(const GridSpec<D>& grid, const NodeList& band, int k, const Context& ctx, NodeList& dilated,
  const NodeList* more = nullptr);

/// (1.49) on the listed nodes: phi clamped to [-gamma, gamma].
template <int D>
void cutLevelSet(GridField<D, double>& phi, const NodeList& nodes, double gamma, const Context& ctx);

/// (1.49) on every interior node (ghosts are not touched).
template <int D>
void cutLevelSet(GridField<D, double>& phi, double gamma, const Context& ctx);

extern template void collectBand(const GridField<2, double>&, double, const Context&, NodeList&);
extern template void collectBand(const GridField<3, double>&, double, const Context&, NodeList&);
extern template void filterBand(const GridField<2, double>&, const NodeList&, double, const Context&, NodeList&);
extern template void filterBand(const GridField<3, double>&, const NodeList&, double, const Context&, NodeList&);
extern template void dilateBand(const GridSpec<2>&, const NodeList&, int, const Context&, NodeList&, const NodeList*);
extern template void dilateBand(const GridSpec<3>&, const NodeList&, int, const Context&, NodeList&, const NodeList*);
extern template void cutLevelSet(GridField<2, double>&, const NodeList&, double, const Context&);
extern template void cutLevelSet(GridField<3, double>&, const NodeList&, double, const Context&);
extern template void cutLevelSet(GridField<2, double>&, double, const Context&);
extern template void cutLevelSet(GridField<3, double>&, double, const Context&);

} // namespace sltk
