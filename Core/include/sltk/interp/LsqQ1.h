// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file LsqQ1.h
/// The interpolation of the thesis's adaptive scheme (5.2.1, (5.5)) on a
/// uniform grid: the value at x comes from the polynomial of the cell whose
/// centre is nearest to x. On the thesis's trees the values sit at quadrant
/// centres; here they sit at nodes, so "the quadrant i" is the node nearest
/// to x and its neighbours are the 3^D - 1 nodes around it (edge and corner
/// neighbours, Fig. 5.3). The polynomial is Q1 in x' = (x - x_i) / dx,
/// p_i = sum_k c_k phi_k(x') with the basis {1, x'_1, x'_2, x'_1 x'_2} (2D) or
/// its trilinear analogue (3D), fitted to the neighbours' values by least
/// squares with the constraint p_i(x_i) = phi_i (c_0 = phi_i, "the reduced
/// system").
///
/// On a uniform stencil the reduced system is diagonal: every basis monomial
/// m_S = prod_{a in S} x'_a is odd in some axis, so the monomials are
/// orthogonal over the offsets {-1, 0, 1}^D and c_S = sum_o m_S(o) phi(i + o) /
/// (2^|S| 3^(D - |S|)). That is a tensor product of the 1D operators
/// "average" (v_-1 + v_0 + v_1) / 3 and "half difference" (v_1 - v_-1) / 2, so
///   p_i(x') = [prod_a (avg_a + x'_a diff_a)] phi - [prod_a avg_a] phi + phi_i,
/// which eval() computes axis by axis, as Q1 and WENO3 do. The second term is
/// the mean of the 3^D values (the unconstrained c_0); collapsing it with the
/// same operations as the first makes p_i(x_i) = phi_i exactly.
///
/// The polynomial has degree one in each variable and reproduces multilinear
/// data (second-order accurate on smooth data, its slopes central
/// differences), but, as the thesis notes (5.3.1), it jumps where the nearest
/// node changes (t = 1/2 along an axis; O(h^3) on smooth data, more at kinks);
/// it is here for the side-by-side comparison with the thesis's scheme
/// (Documentation/Octree.md).

#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"

#include <array>
#include <cassert>

namespace sltk
{

/// p_i(x') from the 3^D values around node i (x fastest): the tensor product
/// of the header, collapsing the last axis first (its triples sit at stride 3^a).
/// On the first axis both products collapse the same triples, so the average's
/// first pass is the full product's mean of each triple (the same division).
/// V is double, or a vector of lanes that each make these operations in this
/// order (LsqQ1Lanes.h), into `out` (vectors by reference: returned by value
/// they would change the ABI).
template <int D, class V>
SLTK_LANES_INLINE void lsqQ1Fit(const V* around, const V* x, V& out)
{
  constexpr int Neighbours = ipow(3, D);
  V full[Neighbours / 3], average[Neighbours / 3];
  int n = Neighbours / 3;
  for (int c = 0; c < n; ++c)
  {
    const V mean = (around[c] + around[c + n] + around[c + 2 * n]) / 3.0;
    full[c] = mean + x[D - 1] * 0.5 * (around[c + 2 * n] - around[c]);
    average[c] = mean;
  }
  for (int a = D - 2; a >= 0; --a)
  {
    n /= 3;
    for (int c = 0; c < n; ++c)
    {
      const V line = full[c] + full[c + n] + full[c + 2 * n];
      full[c] = line / 3.0 + x[a] * 0.5 * (full[c + 2 * n] - full[c]);
      average[c] = (average[c] + average[c + n] + average[c + 2 * n]) / 3.0;
    }
  }
  out = full[0] - average[0] + around[Neighbours / 2];
}

template <int D>
class LsqQ1Interpolator
{
public:
  static constexpr int Dim = D;
  static constexpr int GhostWidth = 2; ///< the nearest node's neighbours: nodes -1..2 of the cell
  static constexpr int Neighbours = ipow(3, D);

  explicit LsqQ1Interpolator(const GridField<D, double>& field)
    : Stencil(field, -1) // stencil digit 0..3 is node -1..2 along each axis
  {
    assert(field.ghost() >= GhostWidth);
  }

  /// Caches the 4^D nodes around the cell: the 3^D neighbourhoods of its 2^D corners.
  void prepare(const std::array<Index, D>& cell) { this->Stencil.prepare(cell); }
  void prepareIfNeeded(const std::array<Index, D>& cell) { this->Stencil.prepareIfNeeded(cell); }

  /// p_i(x') of the corner i nearest to local coordinates t in [0, 1]^D.
  double eval(const std::array<double, D>& t) const
  {
    // The corner: node k_a = round(t_a) of the cell along each axis; its neighbourhood's digits k_a .. k_a + 2.
    const Nearest near = nearest(t);
    double around[Neighbours];
    for (int c = 0; c < Neighbours; ++c)
    {
      int rest = c, digit = near.First, place = 1;
      for (int a = 0; a < D; ++a)
      {
        digit += (rest % 3) * place;
        rest /= 3;
        place *= 4;
      }
      around[c] = this->Stencil[digit];
    }
    double value = 0.0;
    lsqQ1Fit<D>(around, near.X.data(), value);
    return value;
  }

  /// The same value at `loc` read straight from `field` (no 4^D cache: the 3^D
  /// nodes around the nearest corner only), `around` being
  /// stencilOffsets<D, 3>(field.strides(), -1). The step's feet (LevelSetStep.h).
  static double evalAt(
    const GridField<D, double>& field, const std::array<Index, Neighbours>& around, const CellLocation<D>& loc)
  {
    const Nearest near = nearest(loc.Local);
    std::array<Index, D> node = loc.Cell;
    for (int a = 0; a < D; ++a)
    {
      node[a] += near.Corner[a];
    }
    const double* p = field.pointer(node);
    double values[Neighbours];
    for (int c = 0; c < Neighbours; ++c)
    {
      values[c] = p[around[c]];
    }
    double value = 0.0;
    lsqQ1Fit<D>(values, near.X.data(), value);
    return value;
  }

  /// The node of the cell nearest to local coordinates t, and t from it.
  struct Nearest
  {
    std::array<int, D> Corner{}; ///< k_a in {0, 1}
    std::array<double, D> X{};   ///< x'_a = t_a - k_a
    int First = 0;               ///< the 4^D stencil's digit of the corner's neighbourhood's first node
  };

  static Nearest nearest(const std::array<double, D>& t)
  {
    Nearest n;
    int stride = 1;
    for (int a = 0; a < D; ++a)
    {
      n.Corner[a] = t[a] >= 0.5 ? 1 : 0;
      n.X[a] = t[a] - n.Corner[a];
      n.First += n.Corner[a] * stride;
      stride *= 4;
    }
    return n;
  }

private:
  StencilCache<D, 4> Stencil;
};

} // namespace sltk
