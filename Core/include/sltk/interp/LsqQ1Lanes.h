// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LsqQ1Lanes.h
/// The least-squares Q1 of the thesis's adaptive scheme (5.5) (LsqQ1.h) at
/// the 2^(d-1) feet of a node of the SL step (4.22)/(4.24) at once, one foot
/// per SIMD lane (Lanes.h): each foot reads the 3^D nodes around its own
/// nearest node, and the fit's tensor-product passes (lsqQ1Fit) are the same
/// for all of them, so 13 passes of four lanes replace 52 of one (3D), with
/// the divisions of four feet in one instruction. A lane's value is
/// LsqQ1Interpolator::evalAt's bit for bit (TestLsqQ1Lanes).

#include "sltk/grid/GridField.h"
#include "sltk/interp/FeetLanes.h"
#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"
#include "sltk/interp/LsqQ1.h"

#include <array>
#include <cstring>

namespace sltk
{

/// LsqQ1Interpolator::evalAt at 2^(D-1) located points of one field.
template <int D>
class LsqQ1Lanes : public FeetLanes<LsqQ1Lanes<D>, D>
{
public:
  using FeetLanes<LsqQ1Lanes<D>, D>::Count;
  static constexpr int Neighbours = LsqQ1Interpolator<D>::Neighbours;

  explicit LsqQ1Lanes(const GridField<D, double>& field)
    : Field(&field)
    , Around(stencilOffsets<D, 3>(field.strides(), -1))
  {
  }

private:
  friend class FeetLanes<LsqQ1Lanes<D>, D>;
  using Vec = lanes::Lanes<Count>;

  SLTK_LANES_INLINE void evalLanes(const std::array<CellLocation<D>, Count>& at, double* out) const
  {
    // Lanes are filled through arrays (a vector of a dependent size cannot be subscripted in a template).
    const double* centre[Count];
    alignas(sizeof(Vec)) double x[D][Count];
    for (int l = 0; l < Count; ++l)
    {
      const auto near = LsqQ1Interpolator<D>::nearest(at[l].Local);
      std::array<Index, D> node = at[l].Cell;
      for (int a = 0; a < D; ++a)
      {
        node[a] += near.Corner[a];
        x[a][l] = near.X[a];
      }
      centre[l] = this->Field->pointer(node);
    }
    alignas(sizeof(Vec)) double values[Neighbours][Count];
    for (int c = 0; c < Neighbours; ++c)
    {
      for (int l = 0; l < Count; ++l)
      {
        values[c][l] = centre[l][this->Around[c]];
      }
    }
    // Read in place as vectors (the lane types may alias double).
    Vec fit;
    lsqQ1Fit<D>(reinterpret_cast<const Vec*>(&values[0][0]), reinterpret_cast<const Vec*>(&x[0][0]), fit);
    std::memcpy(out, &fit, sizeof(Vec));
  }

  const GridField<D, double>* Field;
  std::array<Index, Neighbours> Around;
};

} // namespace sltk
