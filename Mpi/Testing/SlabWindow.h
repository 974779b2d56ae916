// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabWindow.h
/// A rank's window of a whole-grid field for the slab tests of Mpi/: the rows
/// slab.First .. slab.Stop - 1 of the last axis, at the whole grid's
/// coordinates (GridSpec::Offset), its ghost layers filled by extrapolation.
#include "sltk/grid/GridField.h"
#include "sltk/grid/Slabs.h"

template <int D>
sltk::GridField<D> windowOf(const sltk::GridField<D>& whole, const sltk::SlabPlan& slab)
{
  sltk::GridSpec<D> spec = whole.spec();
  spec.Dims[D - 1] = slab.windowRows();
  spec.Offset[D - 1] = whole.spec().Offset[D - 1] + slab.First;
  sltk::GridField<D> part(spec, whole.ghost());
  const sltk::Index rowNodes = spec.nodeCount() / spec.Dims[D - 1];
  for (sltk::Index k = 0; k < spec.nodeCount(); ++k)
  {
    part(part.nodeIndex(k)) = whole(whole.nodeIndex(k + slab.First * rowNodes));
  }
  part.fillGhosts();
  return part;
}
