// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file CwenoIndicator.h
/// Oscillation indicators of the CWENO reconstruction as quadratic forms of the
/// tensor monomial coefficients (CwenoPolynomial.h):
///
///   OSC[P] = sum_{|alpha| >= 2} Delta^(2|alpha| - 2 - D) int_cell (d^alpha P)^2 dV,
///
/// which is (3.18) for D = 1 (Delta = dx) and (3.24) for D = 2 (Delta = the cell
/// diameter, integral over the cell in dx dy: Documentation/Numerics.md), and the same scaling in
/// 3D: the exponent keeps OSC ~ 1 across a kink and OSC = O(h^2) on smooth data
/// (a kink makes d^alpha P ~ h^(1-|alpha|), the cell has volume h^D).
///
/// With P = sum_j z_j prod_a t_a^(j_a), t_a = (x_a - x_{i_a}) / h_a, the form is
/// OSC = z^T M z with (the 1D integrals factorise)
///   M_jk = sum_alpha c_alpha prod_a I^(alpha_a)_(j_a k_a),
///   c_alpha = Delta^(2|alpha| - 2 - D) prod_a h_a^(1 - 2 alpha_a),
///   I^a_jk = int_0^1 (d^a t^j)(d^a t^k) dt = j!/(j-a)! k!/(k-a)! / (j + k - 2a + 1).
/// On a uniform grid M = M_ref / dx^2: the matrix M of (3.25), printed in the
/// Appendix and by bench/derive/derive_cweno.py.

#include "sltk/interp/CwenoPolynomial.h"
#include "sltk/interp/Lanes.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace sltk
{
namespace cweno
{

/// I^a_jk = int_0^1 (d^a t^j / dt^a)(d^a t^k / dt^a) dt.
inline double derivativeIntegral(int a, int j, int k)
{
  if (j < a || k < a)
  {
    return 0.0;
  }
  double fj = 1.0;
  double fk = 1.0;
  for (int m = 0; m < a; ++m)
  {
    fj *= static_cast<double>(j - m);
    fk *= static_cast<double>(k - m);
  }
  return fj * fk / static_cast<double>(j + k - 2 * a + 1);
}

/// Total degree of monomial p of the N^D layout (CwenoPolynomial.h).
template <int D, int N>
constexpr int monomialDegree(int p)
{
  int order = 0;
  for (int a = 0; a < D; ++a, p /= N)
  {
    order += p % N;
  }
  return order;
}

/// The quadratic form OSC = z^T M z of polynomials with N coefficients per axis
/// (N = 4: the optimal polynomial, N = 3: the octant polynomials), for the given
/// spacings and scaling length Delta. Building M is O(N^(3D)) operations (about a
/// millisecond in 3D), so the forms of one (spacing, Delta) are built once and
/// shared by every interpolator of that grid, whichever thread or chunk
/// constructs them: a form is a pointer to read-only entries.
template <int D, int N>
class IndicatorForm
{
public:
  static constexpr int Size = ipow(N, D);

  IndicatorForm(const std::array<double, D>& spacing, double delta)
    : Shared(sharedEntries(spacing, delta))
    , Upper(Shared->Upper.data())
  {
  }

  /// The forms of the last KeptGrids (spacing, Delta) asked for are kept even
  /// while no form holds them: chunks that run one after the other (one thread,
  /// an MPI rank of one thread) find them built.
  static constexpr size_t KeptGrids = 8;

private:
  struct Entries
  {
    std::vector<double> Matrix; ///< dense M, row-major
    std::vector<double> Upper;  ///< U: upper triangle of the active block, off-diagonal doubled, packed by columns
  };

  /// The entries of (spacing, delta): those already built for the same values
  /// (equal doubles), else built now. Kept for the KeptGrids most recent keys.
  static std::shared_ptr<const Entries> sharedEntries(const std::array<double, D>& spacing, double delta)
  {
    using Key = std::array<double, D + 1>;
    // Never destroyed: a form may still be built while the process's statics are destroyed.
    static std::mutex& guard = *new std::mutex;
    static auto& recent = *new std::vector<std::pair<Key, std::shared_ptr<const Entries>>>; // most recent first
    Key key{};
    std::copy(spacing.begin(), spacing.end(), key.begin());
    key[D] = delta;
    const std::lock_guard<std::mutex> lock(guard);
    auto found = std::find_if(recent.begin(), recent.end(), [&](const auto& k) { return k.first == key; });
    if (found == recent.end())
    {
      ++builtCount();
      recent.emplace(recent.begin(), key, build(spacing, delta));
      if (recent.size() > KeptGrids)
      {
        recent.pop_back();
      }
      return recent.front().second;
    }
    std::rotate(recent.begin(), found, found + 1); // to the front
    return recent.front().second;
  }

  static std::atomic<std::uint64_t>& builtCount()
  {
    static std::atomic<std::uint64_t>& count = *new std::atomic<std::uint64_t>(0); // never destroyed
    return count;
  }

  static std::shared_ptr<const Entries> build(const std::array<double, D>& spacing, double delta)
  {
    auto out = std::make_shared<Entries>();
    std::vector<double>& matrix = out->Matrix;
    matrix.assign(static_cast<size_t>(Size) * Size, 0.0);
    // c_alpha for every multi-index alpha with alpha_a <= N - 1 (alpha laid out like j).
    double weight[Size];
    for (int al = 0; al < Size; ++al)
    {
      int rest = al;
      int order = 0;
      double c = 1.0;
      for (int a = 0; a < D; ++a)
      {
        const int alpha = rest % N;
        rest /= N;
        order += alpha;
        c *= std::pow(spacing[a], 1 - 2 * alpha);
      }
      weight[al] = order >= 2 ? c * std::pow(delta, 2 * order - 2 - D) : 0.0;
    }
    double integral[N][N][N];
    for (int a = 0; a < N; ++a)
    {
      for (int j = 0; j < N; ++j)
      {
        for (int k = 0; k < N; ++k)
        {
          integral[a][j][k] = derivativeIntegral(a, j, k);
        }
      }
    }
    for (int p = 0; p < Size; ++p)
    {
      for (int q = 0; q < Size; ++q)
      {
        double m = 0.0;
        for (int al = 0; al < Size; ++al)
        {
          if (weight[al] == 0.0)
          {
            continue;
          }
          double term = weight[al];
          int rp = p;
          int rq = q;
          int ra = al;
          for (int a = 0; a < D; ++a)
          {
            term *= integral[ra % N][rp % N][rq % N];
            rp /= N;
            rq /= N;
            ra /= N;
          }
          m += term;
        }
        matrix[static_cast<size_t>(p) * Size + q] = m;
      }
    }
    constexpr std::array<int, ActiveCount> active = activeMonomials();
    for (int j = 0; j < ActiveCount; ++j)
    {
      for (int i = 0; i <= j; ++i)
      {
        out->Upper.push_back((i == j ? 1.0 : 2.0) * matrix[static_cast<size_t>(active[i]) * Size + active[j]]);
      }
    }
    return out;
  }

public:
  /// Monomials of total degree >= 2: the rows of M that are not zero (the
  /// others have no derivative of order >= 2), in increasing index order.
  static constexpr int ActiveCount = []
  {
    int count = 0;
    for (int p = 0; p < Size; ++p)
    {
      count += monomialDegree<D, N>(p) >= 2 ? 1 : 0;
    }
    return count;
  }();
  static constexpr std::array<int, ActiveCount> activeMonomials()
  {
    std::array<int, ActiveCount> active{};
    for (int p = 0, i = 0; p < Size; ++p)
    {
      if (monomialDegree<D, N>(p) >= 2)
      {
        active[i++] = p;
      }
    }
    return active;
  }

  /// OSC[P] = z^T M z for the coefficients z (Size values).
  double operator()(const double* z) const
  {
    constexpr std::array<int, ActiveCount> active = activeMonomials();
    double y[ActiveCount];
    for (int i = 0; i < ActiveCount; ++i)
    {
      y[i] = z[active[i]];
    }
    return this->ofActive(y);
  }

  /// OSC[P] from the coefficients y of the active monomials only (activeMonomials() order).
  double ofActive(const double* y) const
  {
    double osc = 0.0;
    this->ofActiveLanes<1>(y, &osc);
    return osc;
  }

  /// OSC of L polynomials at once, y[i * L + l] the active coefficient i of
  /// polynomial l, into osc[l]: s = sum_i y_i r_i with r_i = sum_{j >= i} U_ij y_j,
  /// U the upper triangle of M on the active monomials, off-diagonal entries doubled.
  /// The r_i are accumulated column by column, all in registers once the loops
  /// are unrolled (no horizontal sums, no serial chain through memory); each
  /// polynomial gets the same operations in the same order, one per lane. T is
  /// double or a SIMD vector (Lanes.h) holding that polynomial of several cells.
  template <int L, class T = double>
  SLTK_LANES_INLINE void ofActiveLanes(const T* y, T* osc) const
  {
    const double* u = this->Upper;
    T r[ActiveCount][L] = {};
#pragma GCC unroll 16
    for (int j = 0; j < ActiveCount; ++j)
    {
      const double* column = u + j * (j + 1) / 2; // U_0j .. U_jj
#pragma GCC unroll 16
      for (int i = 0; i <= j; ++i)
      {
        for (int l = 0; l < L; ++l)
        {
          r[i][l] += column[i] * y[j * L + l];
        }
      }
    }
    for (int l = 0; l < L; ++l)
    {
      T s = {};
#pragma GCC unroll 16
      for (int i = 0; i < ActiveCount; ++i)
      {
        s += y[i * L + l] * r[i][l];
      }
      osc[l] = s;
    }
  }

  /// M_pq (for tests and for printing the Appendix matrices).
  double entry(int p, int q) const
  {
    return this->Shared->Matrix[static_cast<size_t>(p) * Size + q];
  }

  /// Forms built so far for this D and N, over the process (tests).
  static std::uint64_t builds()
  {
    return builtCount().load();
  }

  /// Whether two forms read the same entries (built once: tests).
  bool sharesEntriesWith(const IndicatorForm& o) const
  {
    return this->Shared == o.Shared;
  }

private:
  std::shared_ptr<const Entries> Shared;
  const double* Upper; ///< Shared->Upper.data(), read by ofActiveLanes()
};

} // namespace cweno
} // namespace sltk
