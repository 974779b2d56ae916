// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Interpolator.h
/// The interpolator concept shared by every reconstruction in SLTK
/// (Documentation/Architecture.md, "Adding an interpolator"). An interpolator type `I` for dimension D:
///
///   static constexpr int Dim = D;
///   static constexpr int GhostWidth;           // ghost layers it reads (Q1: 1, others: 2)
///   explicit I(const GridField<D, double>& f); // bind to nodal data (ghosts filled)
///   void prepare(const std::array<Index, D>& cell); // build what depends on the cell only
///   double eval(const std::array<double, D>& local) const; // local coords in [0,1]^D
///
/// plus the free helper sltk::interpolate(interp, x) below, which locates x,
/// prepares the cell when it changed and evaluates. An interpolator object
/// holds per-cell scratch, so use one object per thread. The thesis's point
/// (Remarks 3.1-3.2) is that CWENO builds one polynomial per cell in prepare()
/// and evaluates it cheaply many times; WENO3 has point-dependent linear
/// weights and does all its work in eval().

#include "sltk/grid/GridField.h"

#include <array>

namespace sltk
{

/// base^exponent for stencil sizes (4^D, 3^D) at compile time.
constexpr int ipow(int base, int exponent)
{
  return exponent == 0 ? 1 : base * ipow(base, exponent - 1);
}

/// Tracks the prepared cell so that repeated evaluations in one cell skip prepare().
template <int D>
struct PreparedCell
{
  std::array<Index, D> Cell{};
  bool Valid = false;

  bool matches(const std::array<Index, D>& c) const { return this->Valid && c == this->Cell; }
  void set(const std::array<Index, D>& c)
  {
    this->Cell = c;
    this->Valid = true;
  }
};

/// Storage offsets of the W^D stencil nodes of a cell relative to its lower
/// corner node, for strides `s` (x fastest): stencil digit c along an axis is
/// node c + first (WENO3/CWENO: W = 4, first = -1, nodes -1..2).
template <int D, int W>
inline std::array<Index, ipow(W, D)> stencilOffsets(const std::array<Index, D>& s, int first)
{
  std::array<Index, ipow(W, D)> offset{};
  for (int c = 0; c < ipow(W, D); ++c)
  {
    Index o = 0;
    int rest = c;
    for (int a = 0; a < D; ++a)
    {
      o += static_cast<Index>(rest % W + first) * s[a];
      rest /= W;
    }
    offset[c] = o;
  }
  return offset;
}

/// The values of the W^D nodes around a cell (nodes first .. first + W - 1 along
/// each axis, digit c of the stencil x fastest), read once per cell: the
/// prepare() of interpolators that do all their work in eval() (WENO3, the
/// least squares Q1 of LsqQ1.h).
template <int D, int W>
class StencilCache
{
public:
  static constexpr int Size = ipow(W, D);

  StencilCache(const GridField<D, double>& field, int first)
    : Field(&field)
    , Offset(stencilOffsets<D, W>(field.strides(), first))
  {
  }

  void prepare(const std::array<Index, D>& cell)
  {
    const double* p = this->Field->pointer(cell);
    for (int c = 0; c < Size; ++c)
    {
      this->Values[c] = p[this->Offset[c]];
    }
    this->Prepared.set(cell);
  }

  void prepareIfNeeded(const std::array<Index, D>& cell)
  {
    if (!this->Prepared.matches(cell))
    {
      this->prepare(cell);
    }
  }

  double operator[](int c) const { return this->Values[c]; }

private:
  const GridField<D, double>* Field;
  std::array<Index, Size> Offset{};
  double Values[Size] = {};
  PreparedCell<D> Prepared;
};

/// Interpolates at a physical point x (clipped or wrapped per the grid's boundary policy).
template <class Interp>
inline double interpolate(Interp& interp, const GridSpec<Interp::Dim>& spec, const double* x)
{
  const auto loc = locate(spec, x);
  interp.prepareIfNeeded(loc.Cell);
  return interp.eval(loc.Local);
}

} // namespace sltk
