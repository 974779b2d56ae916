// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Minimizer.h
/// The minimisation in (3.7) over discrete controls a = (a_1, ..., a_nu) in
/// A^nu, as described in 3.2 ("tabulation on the points (a_j, ..., a_j) for
/// a_j in a coarsened grid in A, followed by a Nelder-Mead algorithm, adjusted
/// so that no vertex of the simplices could exit the compact set A"):
///  1. tabulation: the objective on the constant sequences (a, ..., a), a on
///     ControlSet::tabulation(TabulationPoints) (a finite set with nu > 1 is
///     enumerated over all of A^nu when that has at most 4096 elements);
///  2. local search from the best tabulated sequence, in the parameters of
///     ControlSet (one block per stage when PerStageControls):
///     - golden section on [p* - h, p* + h] (h the tabulation spacing, clipped
///       to A) when there is a single parameter (Test 2, Table 3.3: the
///       minimiser's accuracy shows at N = 641, hence a tight tolerance);
///     - otherwise Nelder-Mead whose trial vertices are projected onto A.
/// The result is never worse than the best tabulated value. Evaluations are
/// counted (the "reconstructions per node" of Figures 3.4-3.6).
///
/// Warm start (beyond the thesis, off by default): minimizeFrom() replaces the
/// fine tabulation of A by a coarse WarmTabulationPoints^q tabulation of A plus
/// a WarmTabulationPoints^q grid of the fine spacing centred on a given
/// parameter vector (the node's argmin at the previous time step), then runs
/// the same local search. Where the argmin moves smoothly in time (Test 4) it
/// finds the same minima with far fewer evaluations; where the global minimum
/// sits in a narrow basin the coarse grid misses, it can miss it, so the
/// caller decides (HjbOptions, the Test 4 preset).

#include "sltk/hjb/ControlSet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace sltk
{

enum class LocalSearch : std::uint8_t
{
  Auto = 0,       ///< golden section for one parameter, Nelder-Mead otherwise
  None = 1,       ///< tabulation only
  NelderMead = 2, ///< projected Nelder-Mead
  Golden = 3      ///< golden section (one parameter only; otherwise Nelder-Mead)
};

struct MinimizerOptions
{
  int TabulationPoints = 33;    ///< per axis of A (circle: angles)
  bool PerStageControls = true; ///< minimise over A^nu (3.7)-(3.8); false: one control for all stages
  LocalSearch Search = LocalSearch::Auto;
  double Tolerance = 1e-9;       ///< on the parameters: simplex size, golden bracket
  double ValueTolerance = 1e-15; ///< Nelder-Mead also stops when the values differ by less (relative)
  int MaxIterations = 1000;      ///< Nelder-Mead iterations
  /// > 0: warm start from the previous argmin on this many points per
  /// parameter (odd; 5 on Test 4), see minimizeFrom(); 0: always tabulate A.
  int WarmTabulationPoints = 0;
};

/// Discrete control (a_1, ..., a_S) of one RK step, (3.5).
template <int M, int S>
using ControlSequence = std::array<std::array<double, M>, S>;

template <int M, int S>
struct MinimizerResult
{
  ControlSequence<M, S> Controls{};
  /// Local-search parameters of Controls (the first ControlMinimizer::parameterCount()).
  std::array<double, M * S> Arguments{};
  double Value = std::numeric_limits<double>::infinity();
  int Evaluations = 0;
};

/// Minimiser of F(a) over A^S; build once per step (it tabulates A), then call
/// minimize() concurrently (it is const and allocation-free).
template <int M, int S>
class ControlMinimizer
{
public:
  static constexpr int MaxParameters = M * S;
  using Sequence = ControlSequence<M, S>;
  using Parameters = std::array<double, MaxParameters>;

  ControlMinimizer(const ControlSet<M>& set, const MinimizerOptions& options)
    : Set(set)
    , Options(options)
  {
    const int q = set.parameterCount();
    this->Blocks = options.PerStageControls ? S : 1;
    this->Count = q * this->Blocks;
    this->Step = set.tabulationSpacing(options.TabulationPoints);
    this->CoarseStep = set.tabulationSpacing(options.WarmTabulationPoints);
    if (set.empty())
    {
      this->Table.push_back(Sequence{});
      this->TableParameters.push_back(Parameters{});
      return;
    }
    const std::vector<typename ControlSet<M>::Control> grid = set.tabulation(options.TabulationPoints);
    if (set.Kind == ControlKind::Finite && options.PerStageControls && S > 1)
    {
      double total = 1.0;
      for (int k = 0; k < S; ++k)
      {
        total *= static_cast<double>(grid.size());
      }
      if (total <= 4096.0)
      {
        const size_t n = grid.size();
        for (size_t code = 0; code < static_cast<size_t>(total); ++code)
        {
          Sequence a{};
          size_t rest = code;
          for (int k = 0; k < S; ++k)
          {
            a[k] = grid[rest % n];
            rest /= n;
          }
          this->Table.push_back(a);
          this->TableParameters.push_back(Parameters{});
        }
        return;
      }
    }
    this->tabulateConstant(grid, this->Table, this->TableParameters);
    if (this->warmStarts())
    {
      this->tabulateConstant(set.tabulation(options.WarmTabulationPoints), this->CoarseTable, this->CoarseParameters);
    }
  }

  /// Number of local-search parameters (0: tabulation only).
  int parameterCount() const { return this->Count; }
  /// Number of tabulated sequences.
  int tabulationSize() const { return static_cast<int>(this->Table.size()); }

  /// The only candidate when A^S is one sequence (no parameters and a table of
  /// one entry, Test 1's A = {}), else nullptr: minimize() is then
  /// candidateValue(objective(*onlyCandidate())) in one evaluation.
  const Sequence* onlyCandidate() const
  {
    return this->Count == 0 && this->Table.size() == 1 ? &this->Table[0] : nullptr;
  }

  /// An objective value as the minimisation compares it: NaN counts as +inf.
  static double candidateValue(double v) { return std::isnan(v) ? std::numeric_limits<double>::infinity() : v; }

  /// Controls of admissible parameters.
  Sequence sequence(const Parameters& p) const
  {
    Sequence a{};
    const int q = this->Set.parameterCount();
    for (int k = 0; k < S; ++k)
    {
      const int b = this->Blocks == 1 ? 0 : k;
      a[k] = this->Set.fromParameters(p.data() + b * q);
    }
    return a;
  }

  /// argmin over A^S of objective(const Sequence&) -> double. NaN counts as +inf.
  template <class Objective>
  MinimizerResult<M, S> minimize(Objective&& objective) const
  {
    MinimizerResult<M, S> r;
    scanTable(objective, this->Table, this->TableParameters, r);
    this->localSearch(objective, r, this->Step);
    return r;
  }

  /// True when minimizeFrom() applies (local-search parameters and WarmTabulationPoints > 0).
  bool warmStarts() const { return this->Count > 0 && this->Options.WarmTabulationPoints > 0; }

  /// Warm-started argmin. The candidates are a coarse WarmTabulationPoints^q
  /// tabulation of A (constant controls: it catches the jumps of the argmin
  /// between basins, e.g. at the top of the Test 4 cap) and `start` shifted in
  /// every block by the offsets of a WarmTabulationPoints^q grid of the fine
  /// tabulation spacing (projected onto A); then the local search of
  /// minimize(). Requires warmStarts().
  template <class Objective>
  MinimizerResult<M, S> minimizeFrom(Objective&& objective, const Parameters& start) const
  {
    MinimizerResult<M, S> r;
    scanTable(objective, this->CoarseTable, this->CoarseParameters, r);
    const int q = this->Set.parameterCount();
    const int w = this->Options.WarmTabulationPoints;
    int total = 1;
    for (int j = 0; j < q; ++j)
    {
      total *= w;
    }
    bool interior = false; // the best is inside the fine grid: the argmin is within one fine step
    for (int code = 0; code < total; ++code)
    {
      Parameters p = start;
      int rest = code;
      bool onEdge = false;
      for (int j = 0; j < q; ++j)
      {
        const int k = rest % w - w / 2;
        rest /= w;
        onEdge = onEdge || k == -(w / 2) || k == w / 2;
        for (int b = 0; b < this->Blocks; ++b)
        {
          p[b * q + j] += this->Step * static_cast<double>(k);
        }
      }
      this->projectParameters(p);
      const Sequence a = this->sequence(p);
      const double v = call(objective, a, r);
      if (v < r.Value)
      {
        r.Value = v;
        r.Controls = a;
        r.Arguments = p;
        interior = !onEdge;
      }
    }
    // Otherwise the argmin moved past the fine grid (or jumped to the coarse
    // candidate): search within one coarse step.
    this->localSearch(objective, r, interior ? this->Step : this->CoarseStep);
    return r;
  }

private:
  /// Golden section on r.Arguments +- radius, or Nelder-Mead from r.Arguments
  /// with edges of length radius (Options.Search).
  template <class Objective>
  void localSearch(Objective& objective, MinimizerResult<M, S>& r, double radius) const
  {
    if (this->Count == 0 || this->Options.Search == LocalSearch::None || !std::isfinite(r.Value))
    {
      return;
    }
    const Parameters start = r.Arguments;
    if (this->Count == 1 && this->Options.Search != LocalSearch::NelderMead)
    {
      this->golden(objective, start, radius, r);
    }
    else
    {
      this->nelderMead(objective, start, radius, r);
    }
  }

  /// Appends the constant sequences (c, ..., c) of the controls `grid` and their parameters.
  void tabulateConstant(const std::vector<typename ControlSet<M>::Control>& grid, std::vector<Sequence>& table,
    std::vector<Parameters>& parameters) const
  {
    const int q = this->Set.parameterCount();
    for (const auto& c : grid)
    {
      Sequence a{};
      Parameters p{};
      for (int k = 0; k < S; ++k)
      {
        a[k] = c;
      }
      for (int b = 0; b < this->Blocks; ++b)
      {
        this->Set.toParameters(c, p.data() + b * q);
      }
      table.push_back(a);
      parameters.push_back(p);
    }
  }

  /// Evaluates every entry of a table; r keeps the best (first on ties) if it beats r.Value.
  template <class Objective>
  static void scanTable(Objective& objective, const std::vector<Sequence>& table,
    const std::vector<Parameters>& parameters, MinimizerResult<M, S>& r)
  {
    size_t best = table.size();
    for (size_t j = 0; j < table.size(); ++j)
    {
      const double v = call(objective, table[j], r);
      if (v < r.Value)
      {
        r.Value = v;
        best = j;
      }
    }
    if (best < table.size())
    {
      r.Controls = table[best];
      r.Arguments = parameters[best];
    }
    else if (!std::isfinite(r.Value) && !table.empty())
    {
      r.Controls = table[0]; // all infinite: as before, the first entry
      r.Arguments = parameters[0];
    }
  }

  template <class Objective>
  static double call(Objective& objective, const Sequence& a, MinimizerResult<M, S>& r)
  {
    ++r.Evaluations;
    return candidateValue(objective(a));
  }

  void projectParameters(Parameters& p) const
  {
    const int q = this->Set.parameterCount();
    for (int b = 0; b < this->Blocks; ++b)
    {
      this->Set.projectParameters(p.data() + b * q);
    }
  }

  /// Golden-section search of the single parameter on [p* - h, p* + h] (clipped to A).
  template <class Objective>
  void golden(Objective& objective, const Parameters& start, double radius, MinimizerResult<M, S>& r) const
  {
    double lo = 0.0, hi = 0.0;
    this->Set.parameterBounds(0, lo, hi);
    double a = std::max(lo, start[0] - radius);
    double b = std::min(hi, start[0] + radius);
    constexpr double invPhi = 0.6180339887498949; // (sqrt 5 - 1) / 2
    Parameters p = start;
    auto f = [&](double s)
    {
      p[0] = s;
      const Sequence seq = this->sequence(p);
      const double v = call(objective, seq, r);
      if (v < r.Value)
      {
        r.Value = v;
        r.Controls = seq;
        r.Arguments = p;
      }
      return v;
    };
    double c = b - invPhi * (b - a);
    double d = a + invPhi * (b - a);
    double fc = f(c);
    double fd = f(d);
    const double tol =
      std::max(this->Options.Tolerance, 4.0 * std::numeric_limits<double>::epsilon() * std::fabs(start[0]));
    while (b - a > tol)
    {
      if (fc <= fd)
      {
        b = d;
        d = c;
        fd = fc;
        c = b - invPhi * (b - a);
        fc = f(c);
      }
      else
      {
        a = c;
        c = d;
        fc = fd;
        d = a + invPhi * (b - a);
        fd = f(d);
      }
    }
  }

  /// Nelder-Mead (reflection 1, expansion 2, contraction 1/2, shrink 1/2) with
  /// every trial vertex projected onto A (3.2), started from the tabulated
  /// optimum with edges of the tabulation spacing.
  template <class Objective>
  void nelderMead(Objective& objective, const Parameters& start, double radius, MinimizerResult<M, S>& r) const
  {
    const int n = this->Count;
    std::array<Parameters, MaxParameters + 1> v{};
    std::array<double, MaxParameters + 1> fv{};
    auto eval = [&](Parameters& p)
    {
      this->projectParameters(p);
      return call(objective, this->sequence(p), r);
    };
    v[0] = start;
    fv[0] = r.Value;
    for (int j = 0; j < n; ++j)
    {
      v[j + 1] = start;
      v[j + 1][j] += radius;
      this->projectParameters(v[j + 1]);
      if (std::fabs(v[j + 1][j] - start[j]) < 0.5 * radius) // the step left A: go the other way
      {
        v[j + 1] = start;
        v[j + 1][j] -= radius;
      }
      fv[j + 1] = eval(v[j + 1]);
    }
    std::array<int, MaxParameters + 1> order{};
    for (int iteration = 0; iteration < this->Options.MaxIterations; ++iteration)
    {
      for (int j = 0; j <= n; ++j) // insertion sort of at most 10 vertices by value
      {
        int k = j;
        for (; k > 0 && fv[order[k - 1]] > fv[j]; --k)
        {
          order[k] = order[k - 1];
        }
        order[k] = j;
      }
      const int bestIdx = order[0];
      const int worstIdx = order[n];
      const int secondIdx = order[n - 1 < 0 ? 0 : n - 1];
      double size = 0.0;
      for (int j = 0; j <= n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          size = std::max(size, std::fabs(v[j][i] - v[bestIdx][i]));
        }
      }
      const double spread = fv[worstIdx] - fv[bestIdx];
      if (size <= this->Options.Tolerance ||
        spread <= this->Options.ValueTolerance * std::max(1.0, std::fabs(fv[bestIdx])))
      {
        break;
      }
      Parameters centroid{};
      for (int j = 0; j <= n; ++j)
      {
        if (j == worstIdx)
        {
          continue;
        }
        for (int i = 0; i < n; ++i)
        {
          centroid[i] += v[j][i] / static_cast<double>(n);
        }
      }
      auto along = [&](double t)
      {
        Parameters p{};
        for (int i = 0; i < n; ++i)
        {
          p[i] = centroid[i] + t * (v[worstIdx][i] - centroid[i]);
        }
        return p;
      };
      Parameters xr = along(-1.0);
      const double fr = eval(xr);
      if (fr < fv[bestIdx])
      {
        Parameters xe = along(-2.0);
        const double fe = eval(xe);
        if (fe < fr)
        {
          v[worstIdx] = xe;
          fv[worstIdx] = fe;
        }
        else
        {
          v[worstIdx] = xr;
          fv[worstIdx] = fr;
        }
        continue;
      }
      if (fr < fv[secondIdx])
      {
        v[worstIdx] = xr;
        fv[worstIdx] = fr;
        continue;
      }
      const bool outside = fr < fv[worstIdx];
      Parameters xc = along(outside ? -0.5 : 0.5);
      const double fc = eval(xc);
      if (fc < (outside ? fr : fv[worstIdx]))
      {
        v[worstIdx] = xc;
        fv[worstIdx] = fc;
        continue;
      }
      for (int j = 0; j <= n; ++j) // shrink towards the best vertex
      {
        if (j == bestIdx)
        {
          continue;
        }
        for (int i = 0; i < n; ++i)
        {
          v[j][i] = v[bestIdx][i] + 0.5 * (v[j][i] - v[bestIdx][i]);
        }
        fv[j] = eval(v[j]);
      }
    }
    int bestIdx = 0;
    for (int j = 1; j <= n; ++j)
    {
      if (fv[j] < fv[bestIdx])
      {
        bestIdx = j;
      }
    }
    if (fv[bestIdx] < r.Value)
    {
      r.Value = fv[bestIdx];
      r.Controls = this->sequence(v[bestIdx]);
      r.Arguments = v[bestIdx];
    }
  }

  ControlSet<M> Set;
  MinimizerOptions Options;
  std::vector<Sequence> Table;
  std::vector<Parameters> TableParameters;
  std::vector<Sequence> CoarseTable; ///< warm starts: WarmTabulationPoints^q constant controls
  std::vector<Parameters> CoarseParameters;
  int Blocks = 1;
  int Count = 0;
  double Step = 0.0;       ///< spacing of the tabulation of A
  double CoarseStep = 0.0; ///< spacing of the coarse tabulation of the warm starts
};

} // namespace sltk
