// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Cweno.h
/// CWENO and CWENOZ reconstruction from point values, thesis 3.3 (Definition 3.1):
/// 1D (3.3.1, (3.17)), 2D (3.3.2, (3.23)) and its 3D extension, one class
/// template for all three. In the cell with lower corner `cell`:
///  - the optimal polynomial P_opt is the tensor cubic (bicubic, tricubic) on the
///    4^D stencil t in {-1, 0, 1, 2}^D;
///  - the 2^D low-degree polynomials P_k are the tensor quadratics on the 3^D
///    sub-stencils, one per octant (1D: P_L, P_R; 2D: sw, se, nw, ne);
///  - prepare() computes the indicators (3.18)/(3.24), the nonlinear weights
///    (3.13)/(3.14) and folds P_0 of (3.11) into ONE polynomial (3.15)/(3.16):
///      P_rec = (omega_0 / d_0) P_opt + sum_k (omega_k - omega_0 d_k / d_0) P_k,
///    stored as 4^D monomial coefficients in local coordinates (Remarks 3.1-3.2);
///  - eval() is a tensor Horner evaluation of that polynomial.
///
/// Scaling choices (Documentation/Numerics.md; 3D by extension): Delta = cell diameter
/// sqrt(sum_a h_a^2) in the indicators, epsilon = Delta^2 / D (= dx^2 on the
/// uniform grids of the thesis), l = 2, d_0 = 3/4, d_k = 1/(4 * 2^D). The diameter
/// is the reading of (3.24) that reproduces M of (3.25) and Table 3.1; the
/// Appendix's A_k, A_opt of (3.26) were printed for Delta = dx (TestCweno.cxx).
/// In 3D, tau = |8 OSC_opt - sum_k OSC_k| = O(h^4) on smooth data, the condition
/// of (3.28) ([42, Theorem 24]) for the optimal order of CWENOZ.

#include "sltk/interp/CwenoIndicator.h"
#include "sltk/interp/CwenoPolynomial.h"
#include "sltk/interp/CwenoWeights.h"
#include "sltk/interp/Interpolator.h"
#include "sltk/interp/Lanes.h"

#include <cassert>
#include <cmath>

namespace sltk
{

template <int D, CwenoVariant V = CwenoVariant::Cweno>
class CwenoInterpolator
{
public:
  static constexpr int Dim = D;
  static constexpr int GhostWidth = 2;
  static constexpr CwenoVariant Variant = V;
  static constexpr int Size = cweno::ipow(4, D);    ///< coefficients of P_opt and P_rec
  static constexpr int LowSize = cweno::ipow(3, D); ///< coefficients of each octant polynomial
  static constexpr int Octants = 1 << D;
  static constexpr int WeightCount = 1 + Octants;
  using Weights = std::array<double, WeightCount>;

  explicit CwenoInterpolator(const GridField<D, double>& field)
    : Field(&field)
    , OptimalForm(field.spec().Spacing, cellDiameter(field.spec()))
    , OctantForm(field.spec().Spacing, cellDiameter(field.spec()))
  {
    assert(field.ghost() >= GhostWidth);
    const double delta = cellDiameter(field.spec());
    this->Epsilon = delta * delta / D;
    this->StencilOffset = stencilOffsets<D, 4>(field.strides(), -1); // nodes -1..2 per axis
  }

  /// Builds the reconstruction polynomial of the cell (lower corner index `cell`).
  void prepare(const std::array<Index, D>& cell)
  {
    this->build(cell, this->Coef.data());
    this->Prepared.set(cell);
  }

  /// prepare() writing the Size coefficients of P_rec to `coef` instead
  /// (CellCache.h stores them); weights() and indicators() are this cell's.
  void build(const std::array<Index, D>& cell, double* coef)
  {
    const double* p = this->Field->pointer(cell);
    double u[Size];
    for (int q = 0; q < Size; ++q)
    {
      u[q] = p[this->StencilOffset[q]];
    }
    this->polynomialOf(u, coef, this->Osc.data(), this->Omega.data());
  }

  /// build() of the L = CellLanes cells `cells[l]` into coef[l], one cell per
  /// SIMD lane (Lanes.h), each lane with build()'s operations in its order: the
  /// same coefficients bit for bit (TestCweno.cxx), several builds overlapping
  /// (Documentation/Profile.md). weights() and indicators() are not set.
  void buildLanes(const std::array<Index, D>* cells, double* const* coef) const
  {
#if defined(SLTK_LANES_AVX2)
    if (lanes::hasAvx2())
    {
      this->buildLanesAvx2(cells, coef);
      return;
    }
#endif
    this->buildLanesAny(cells, coef);
  }

  /// buildLanes() without the AVX2 lanes (the SSE2 pairs on x86-64), for the tests.
  void buildLanesAny(const std::array<Index, D>* cells, double* const* coef) const
  {
    this->lanesOf(cells, coef);
  }

  void prepareIfNeeded(const std::array<Index, D>& cell)
  {
    if (!this->Prepared.matches(cell))
    {
      this->prepare(cell);
    }
  }

  /// P_rec at local coordinates t in [0, 1]^D of the prepared cell.
  double eval(const std::array<double, D>& t) const
  {
    return cweno::evalTensor<D, 4>(this->Coef.data(), t);
  }

  /// Nonlinear weights of the prepared cell: [0] the optimal polynomial, [1 + k]
  /// octant k (bit a of k set: the sub-stencil on the high side along axis a).
  const Weights& weights() const
  {
    return this->Omega;
  }
  /// Indicators of the prepared cell, same order (zero for CwenoVariant::Optimal).
  const Weights& indicators() const
  {
    return this->Osc;
  }
  /// Monomial coefficients of P_rec in local coordinates (CwenoPolynomial.h layout).
  const std::array<double, Size>& coefficients() const
  {
    return this->Coef;
  }
  double epsilon() const
  {
    return this->Epsilon;
  }
  static constexpr Weights linearWeights()
  {
    return cweno::LinearWeights<D>::values();
  }

  /// Delta of (3.24): the cell diameter.
  static double cellDiameter(const GridSpec<D>& spec)
  {
    double s = 0.0;
    for (int a = 0; a < D; ++a)
    {
      s += spec.Spacing[a] * spec.Spacing[a];
    }
    return std::sqrt(s);
  }

  static constexpr int CellLanes = 4; ///< cells built at once by buildLanes()

private:
  using Vec = lanes::Lanes<CellLanes>;

#if defined(SLTK_LANES_AVX2)
  SLTK_LANES_AVX2_TARGET void buildLanesAvx2(const std::array<Index, D>* cells, double* const* coef) const
  {
    this->lanesOf(cells, coef);
  }
#endif

  /// buildLanes(): the stencils gathered lane by lane, polynomialOf() on the vectors.
  SLTK_LANES_INLINE void lanesOf(const std::array<Index, D>* cells, double* const* coef) const
  {
    alignas(sizeof(Vec)) double u[Size][CellLanes];
    for (int l = 0; l < CellLanes; ++l)
    {
      const double* p = this->Field->pointer(cells[l]);
      for (int q = 0; q < Size; ++q)
      {
        u[q][l] = p[this->StencilOffset[q]];
      }
    }
    alignas(sizeof(Vec)) double c[Size][CellLanes];
    Vec osc[WeightCount];
    Vec omega[WeightCount];
    // Read in place as vectors (the lane types may alias double).
    this->polynomialOf(reinterpret_cast<const Vec*>(&u[0][0]), reinterpret_cast<Vec*>(&c[0][0]), osc, omega);
    for (int l = 0; l < CellLanes; ++l)
    {
      for (int q = 0; q < Size; ++q)
      {
        coef[l][q] = c[q][l];
      }
    }
  }

  /// The coefficients of P_rec from the stencil data u (4^D values, x
  /// fastest), with the indicators and weights of the cell; T is double or a
  /// vector of lanes, one cell per lane.
  template <class T>
  SLTK_LANES_INLINE void polynomialOf(const T* u, T* coef, T* osc, T* omega) const
  {
    // The 1D coefficients of every line, from which all 1 + 2^D polynomials are read.
    T table[cweno::TableSize<D>];
    cweno::stencilTable<D>(u, table);
    if constexpr (V == CwenoVariant::Optimal)
    {
      cweno::nonlinearWeightsOf<D, V>(osc, this->Epsilon, omega); // the linear weights
      for (int q = 0; q < Size; ++q)
      {
        coef[q] = table[OptimalIndex[q]];
      }
    }
    else
    {
      this->computeIndicators(table, osc);
      cweno::nonlinearWeightsOf<D, V>(osc, this->Epsilon, omega);
      // (3.11) + (3.15)/(3.16) folded into one set of coefficients:
      // P_rec = (omega_0 / d_0) P_opt + sum_k (omega_k - omega_0 d_k / d_0) P_k.
      constexpr double d0 = cweno::LinearWeights<D>::Optimal;
      constexpr double dk = cweno::LinearWeights<D>::Octant;
      const T scale = omega[0] / d0;
      for (int q = 0; q < Size; ++q)
      {
        coef[q] = scale * table[OptimalIndex[q]];
      }
      for (int k = 0; k < Octants; ++k)
      {
        const T beta = omega[1 + k] - scale * dk;
        for (int q = 0; q < LowSize; ++q)
        {
          coef[cweno::quadraticToCubicIndex<D>(q)] += beta * table[OctantIndex[k][q]];
        }
      }
    }
  }

  using OptimalIndicator = cweno::IndicatorForm<D, 4>;
  using OctantIndicator = cweno::IndicatorForm<D, 3>;
  static constexpr std::array<int, Size> OptimalIndex = cweno::optimalIndices<D>();
  static constexpr std::array<std::array<int, LowSize>, Octants> OctantIndex = []
  {
    std::array<std::array<int, LowSize>, Octants> index{};
    for (int k = 0; k < Octants; ++k)
    {
      index[k] = cweno::octantIndices<D>(k);
    }
    return index;
  }();

  /// The indicators (3.12) of P_opt and of the 2^D octant polynomials, from the
  /// table entries of their monomials of degree >= 2; the octants side by side.
  template <class T>
  SLTK_LANES_INLINE void computeIndicators(const T* table, T* osc) const
  {
    constexpr auto optActive = OptimalIndicator::activeMonomials();
    constexpr auto lowActive = OctantIndicator::activeMonomials();
    T y[OptimalIndicator::ActiveCount];
    for (int i = 0; i < OptimalIndicator::ActiveCount; ++i)
    {
      y[i] = table[OptimalIndex[optActive[i]]];
    }
    this->OptimalForm.template ofActiveLanes<1>(y, osc);
    T low[OctantIndicator::ActiveCount * Octants];
    for (int i = 0; i < OctantIndicator::ActiveCount; ++i)
    {
      for (int k = 0; k < Octants; ++k)
      {
        low[i * Octants + k] = table[OctantIndex[k][lowActive[i]]];
      }
    }
    this->OctantForm.template ofActiveLanes<Octants>(low, osc + 1);
  }

  const GridField<D, double>* Field;
  OptimalIndicator OptimalForm;
  OctantIndicator OctantForm;
  double Epsilon = 0.0;
  std::array<Index, Size> StencilOffset{};
  std::array<double, Size> Coef{};
  Weights Omega{};
  Weights Osc{};
  PreparedCell<D> Prepared;
};

template <int D>
using CwenoZInterpolator = CwenoInterpolator<D, CwenoVariant::CwenoZ>;

} // namespace sltk
