// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CellCache.h
/// A per-thread cache of K prepared cells. Remarks 3.1-3.2: CWENO builds one
/// polynomial per cell and evaluates it cheaply, so the many feet of one node
/// (HJB: y_i^n(a) of the tabulation and local search, Figures 3.4-3.6; level
/// sets: the 2^(d-1) points of (4.22)/(4.24)) -- and of the next nodes, whose
/// feet fall in mostly the same cells -- should reuse it. Two layouts:
///  - K <= 8: K interpolators, linear search, round-robin replacement (the
///    most recently hit slot first). K = 1 is plain prepareIfNeeded().
///  - K >= 16 (a power of two): a direct-mapped table indexed by a
///    multiplicative hash of the cell. For CWENO/CWENOZ each entry holds only
///    the 4^D coefficients of the cell's polynomial (3.15)/(3.16), built by one
///    interpolator and evaluated with the same Horner routine as
///    CwenoInterpolator::eval(); other interpolators get one object per entry.
/// Results are bit-identical for every K (prepare() is deterministic).
/// Counts the cell builds (prepare() calls) and evaluations.

#include "sltk/interp/Cweno.h"
#include "sltk/interp/Interpolator.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace sltk
{

namespace detail
{
/// True for the CWENO family, whose prepared state is its polynomial coefficients.
template <class I>
struct IsCwenoInterpolator : std::false_type
{
};
template <int D, CwenoVariant V>
struct IsCwenoInterpolator<CwenoInterpolator<D, V>> : std::true_type
{
};

/// The cache size for CWENO/CWENOZ when nothing else is asked: 4096 stored
/// polynomials (their builds are the expensive part).
constexpr int CwenoCellCacheSize = 4096;

constexpr int log2Exact(int k)
{
  int l = 0;
  while ((1 << l) < k)
  {
    ++l;
  }
  return l;
}
} // namespace detail

template <class Interp, int K>
class CellCache
{
public:
  static_assert(K >= 1 && (K <= 8 || (K & (K - 1)) == 0), "K is 1..8, or a power of two for the hashed table");
  static constexpr int Dim = Interp::Dim;
  static constexpr int Size = K;
  static constexpr bool Hashed = K > 8;
  static constexpr bool StoresPolynomials = Hashed && detail::IsCwenoInterpolator<Interp>::value;

  /// Copies of an interpolator bound to the field: K, or one that builds the
  /// stored CWENO polynomials (CWENO's copies share their indicator forms:
  /// CwenoIndicator.h).
  CellCache(const Interp& prototype, const GridField<Dim, double>& field)
    : Spec(&field.spec())
    , Slots(StoresPolynomials ? 1 : K, prototype)
  {
    this->Keys.fill(-1);
    Index stride = 1;
    for (int a = 0; a < Dim; ++a)
    {
      this->KeyStride[a] = stride;
      stride *= field.spec().Dims[a] + 1;
    }
    if constexpr (StoresPolynomials)
    {
      // Not zeroed: an entry is read only after its key was set and its polynomial built.
      this->Coefficients.reset(new double[static_cast<size_t>(K) * Interp::Size]);
    }
  }

  /// I[U](x) at a physical point (clipped or wrapped by sltk::locate).
  double operator()(const double* x)
  {
    const CellLocation<Dim> loc = locate(*this->Spec, x);
    ++this->Evaluations;
    const Index key = this->keyOf(loc.Cell);
    if constexpr (Hashed)
    {
      const int s = this->slotOf(key);
      if (this->Keys[s] != key)
      {
        this->Keys[s] = key;
        ++this->Builds;
        if constexpr (StoresPolynomials)
        {
          this->Slots[0].build(loc.Cell, this->entry(s));
        }
        else
        {
          this->Slots[s].prepare(loc.Cell);
        }
      }
      if constexpr (StoresPolynomials)
      {
        // CwenoInterpolator::eval() on the stored coefficients.
        return cweno::evalTensor<Dim, 4>(this->entry(s), loc.Local);
      }
      else
      {
        return this->Slots[s].eval(loc.Local);
      }
    }
    else
    {
      int s = this->Last;
      if (this->Keys[s] != key)
      {
        s = -1;
        for (int k = 0; k < K; ++k)
        {
          if (this->Keys[k] == key)
          {
            s = k;
            break;
          }
        }
        if (s < 0)
        {
          s = this->Victim;
          this->Victim = (this->Victim + 1) % K;
          this->Slots[s].prepare(loc.Cell);
          this->Keys[s] = key;
          ++this->Builds;
        }
        this->Last = s;
      }
      return this->Slots[s].eval(loc.Local);
    }
  }

  /// Points evaluated together by evaluate().
  static constexpr int PointLanes = 4;

  /// values[l] = (*this)(points[l]) for l < count <= PointLanes, the same values and
  /// counts. With stored CWENO polynomials the missing cells are built together,
  /// in the SIMD lanes of CwenoInterpolator::buildLanes() (Documentation/Profile.md:
  /// one build waits on its long dependency chains, several overlap); when two
  /// of the points need one entry for different cells, one after the other.
  void evaluate(int count, const double* const* points, double* values)
  {
    if constexpr (StoresPolynomials)
    {
      std::array<CellLocation<Dim>, PointLanes> loc;
      std::array<Index, PointLanes> key{};
      std::array<int, PointLanes> slot{};
      for (int l = 0; l < count; ++l)
      {
        loc[l] = locate(*this->Spec, points[l]);
        key[l] = this->keyOf(loc[l].Cell);
        slot[l] = this->slotOf(key[l]);
        for (int m = 0; m < l; ++m)
        {
          if (slot[m] == slot[l] && key[m] != key[l])
          {
            this->evaluateEach(count, points, values);
            return;
          }
        }
      }
      std::array<std::array<Index, Dim>, Interp::CellLanes> cells;
      std::array<double*, Interp::CellLanes> to;
      int missing = 0;
      for (int l = 0; l < count; ++l)
      {
        if (this->Keys[slot[l]] != key[l]) // the first of the points in this cell
        {
          this->Keys[slot[l]] = key[l];
          cells[missing] = loc[l].Cell;
          to[missing++] = this->entry(slot[l]);
        }
      }
      this->Builds += missing;
      this->Evaluations += count;
      if (missing == 1)
      {
        this->Slots[0].build(cells[0], to[0]);
      }
      else if (missing > 1)
      {
        double spare[Interp::Size];
        for (int l = missing; l < Interp::CellLanes; ++l) // unused lanes repeat a cell
        {
          cells[l] = cells[0];
          to[l] = spare;
        }
        this->Slots[0].buildLanes(cells.data(), to.data());
      }
      for (int l = 0; l < count; ++l)
      {
        values[l] = cweno::evalTensor<Dim, 4>(this->entry(slot[l]), loc[l].Local);
      }
    }
    else
    {
      this->evaluateEach(count, points, values);
    }
  }

  /// prepare() calls so far.
  double builds() const { return this->Builds; }
  /// Interpolations so far.
  double evaluations() const { return this->Evaluations; }

private:
  Index keyOf(const std::array<Index, Dim>& cell) const
  {
    Index key = 0;
    for (int a = 0; a < Dim; ++a)
    {
      key += cell[a] * this->KeyStride[a];
    }
    return key;
  }

  /// The hashed table's entry of a cell key.
  static int slotOf(Index key)
  {
    // Fibonacci hashing: neighbouring cells (also across rows) land in different entries.
    constexpr int shift = 64 - detail::log2Exact(K);
    return static_cast<int>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ULL) >> shift);
  }

  /// The stored polynomial of entry s.
  double* entry(int s) { return this->Coefficients.get() + static_cast<size_t>(s) * Interp::Size; }

  void evaluateEach(int count, const double* const* points, double* values)
  {
    for (int l = 0; l < count; ++l)
    {
      values[l] = (*this)(points[l]);
    }
  }

  const GridSpec<Dim>* Spec;
  std::vector<Interp> Slots;
  std::unique_ptr<double[]> Coefficients;
  std::array<Index, K> Keys{};
  std::array<Index, Dim> KeyStride{};
  int Last = 0;
  int Victim = 0;
  double Builds = 0.0;
  double Evaluations = 0.0;
};

} // namespace sltk
