// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/EnergyFunctional.h"

#include "sltk/interp/Q1.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace sltk
{

namespace
{
/// Index of the lowest set bit of bits != 0.
inline int lowestBit(std::uint64_t bits)
{
#if defined(__GNUC__)
  return __builtin_ctzll(bits);
#else
  int k = 0;
  for (; !(bits & 1); bits >>= 1)
  {
    ++k;
  }
  return k;
#endif
}

inline double powAbs(double v, double p)
{
  const double a = std::fabs(v);
  return p == 1.0 ? a : (p == 2.0 ? a * a : std::pow(a, p));
}

/// The sums of |d|^p and |d|^q over the front, accumulated in one traversal.
struct PowerSums
{
  double First = 0.0;  ///< |d|^P
  double Second = 0.0; ///< |d|^Q (Q = 0: not wanted)

  PowerSums& operator+=(const PowerSums& o)
  {
    this->First += o.First;
    this->Second += o.Second;
    return *this;
  }
  PowerSums scaled(double w) const { return { this->First * w, this->Second * w }; }
};

/// The refinement R of (4.30) compiled for (EnergyOptions' default); others run the same code with R a variable.
constexpr int DefaultRefinement = 5;

/// Per-chunk evaluator: Q1 interpolators of phi and d (4.28) and the cell rules.
template <int D>
class CellEnergy
{
public:
  CellEnergy(const GridField<D, double>& phi, const GridField<D, double>& distance, const EnergyOptions& options)
    : Phi(phi)
    , Distance(distance)
    , DistanceQ1(distance)
    , P(options.P)
    , Q(options.SecondP)
    , R(options.Refinement)
  {
    this->Buffers.resize(4 * static_cast<size_t>(q1SubcellBuffer<D>(std::max(1, this->R))));
    const GridSpec<D>& g = phi.spec();
    double diagonal2 = 0.0;
    double volume = 1.0;
    for (int a = 0; a < D; ++a)
    {
      const double h = g.Spacing[a] / this->R;
      diagonal2 += h * h;
      volume *= h;
    }
    // |I[Phi](x_i')| < sqrt(3)/2 dx' (4.30): half the subcell diagonal.
    this->HalfDiagonal = 0.5 * std::sqrt(diagonal2);
    this->SubcellWeight = options.Measure == SubcellMeasure::Thesis
      ? std::pow(volume, static_cast<double>(D - 1) / D) // (dx')^(n-1)
      : volume / (2.0 * this->HalfDiagonal);             // shell thickness 2h removed
  }

  /// Contribution of the cell with lowest corner `cell`; `front` tells whether it had any.
  PowerSums operator()(const std::array<Index, D>& cell, bool& front)
  {
    front = false;
    const double* p = this->Phi.pointer(cell);
    const auto& s = this->Phi.strides();
    double v[1 << D];
    bool anyNegative = false;
    bool anyOther = false;
    double minAbs = std::fabs(p[0]);
    for (int c = 0; c < (1 << D); ++c)
    {
      Index o = 0;
      for (int a = 0; a < D; ++a)
      {
        o += ((c >> a) & 1) * s[a];
      }
      v[c] = p[o];
      anyNegative = anyNegative || v[c] < 0.0;
      anyOther = anyOther || !(v[c] < 0.0);
      minAbs = std::min(minAbs, std::fabs(v[c]));
    }
    const bool signChange = anyNegative && anyOther;
    if constexpr (D == 2)
    {
      return signChange ? this->segments(cell, v, front) : PowerSums{};
    }
    else
    {
      if (!signChange && minAbs >= this->HalfDiagonal)
      {
        return PowerSums{};
      }
      return this->subcells(cell, front);
    }
  }

private:
  /// (4.29) in 2D: segments between the edge cuts, trapezoidal rule of |d|^p.
  PowerSums segments(const std::array<Index, D>& cell, const double* v, bool& front)
  {
    // Edges as corner pairs (corner c has local coordinates (c & 1, c >> 1)).
    static const int edge[4][2] = { { 0, 1 }, { 1, 3 }, { 2, 3 }, { 0, 2 } };
    std::array<double, D> cut[4];
    bool has[4] = { false, false, false, false };
    int count = 0;
    for (int e = 0; e < 4; ++e)
    {
      const int a = edge[e][0];
      const int b = edge[e][1];
      if ((v[a] < 0.0) != (v[b] < 0.0))
      {
        const double t = v[a] / (v[a] - v[b]); // linear interpolation of phi on the edge
        for (int k = 0; k < D; ++k)
        {
          const double ta = static_cast<double>((a >> k) & 1);
          const double tb = static_cast<double>((b >> k) & 1);
          cut[e][k] = ta + t * (tb - ta);
        }
        has[e] = true;
        ++count;
      }
    }
    this->DistanceQ1.prepareIfNeeded(cell);
    PowerSums sum;
    if (count == 2)
    {
      int first = -1;
      int second = -1;
      for (int e = 0; e < 4; ++e)
      {
        if (has[e])
        {
          (first < 0 ? first : second) = e;
        }
      }
      sum = this->segment(cut[first], cut[second]);
    }
    else if (count == 4)
    {
      // Saddle: the sign at the centre decides which corners are cut off.
      const double centre = 0.25 * (v[0] + v[1] + v[2] + v[3]);
      if ((centre < 0.0) == (v[0] < 0.0))
      {
        sum = this->segment(cut[0], cut[1]);
        sum += this->segment(cut[2], cut[3]); // around corners 1 and 2
      }
      else
      {
        sum = this->segment(cut[0], cut[3]);
        sum += this->segment(cut[1], cut[2]); // around corners 0 and 3
      }
    }
    front = count > 0;
    return sum;
  }

  PowerSums segment(const std::array<double, D>& a, const std::array<double, D>& b)
  {
    double length2 = 0.0;
    for (int k = 0; k < D; ++k)
    {
      const double l = (b[k] - a[k]) * this->Phi.spec().Spacing[k];
      length2 += l * l;
    }
    // Trapezoidal rule; d by Q1 in the cell (linear along the edges).
    const double da = this->DistanceQ1.eval(a);
    const double db = this->DistanceQ1.eval(b);
    const double half = std::sqrt(length2) * 0.5;
    return { half * (powAbs(da, this->P) + powAbs(db, this->P)),
      this->Q > 0.0 ? half * (powAbs(da, this->Q) + powAbs(db, this->Q)) : 0.0 };
  }

  /// (4.30): subcells whose Q1 centre value satisfies |phi| < sqrt(3)/2 dx'.
  PowerSums subcells(const std::array<Index, D>& cell, bool& front)
  {
    return this->R == DefaultRefinement
      ? this->subcellsOf(cell, std::integral_constant<int, DefaultRefinement>{}, front)
      : this->subcellsOf(cell, this->R, front);
  }

  /// subcells() with R an int or a compile-time constant (q1AtSubcellCentres):
  /// phi and d at the R^D centres by one separable pass each (bitwise
  /// Q1Interpolator::eval), summed in the order m_0 fastest.
  template <class Refinement>
  PowerSums subcellsOf(const std::array<Index, D>& cell, Refinement refinement, bool& front)
  {
    const int r = static_cast<int>(refinement);
    const size_t buffer = static_cast<size_t>(q1SubcellBuffer<D>(r));
    double* buffers = this->Buffers.data();
    double corner[1 << D];
    cellCorners<D>(this->Phi, cell, corner);
    const double* phi = q1AtSubcellCentres<D>(corner, refinement, buffers, buffers + buffer);
    cellCorners<D>(this->Distance, cell, corner);
    const double* d = q1AtSubcellCentres<D>(corner, refinement, buffers + 2 * buffer, buffers + 3 * buffer);
    // The centres on the front as bits, 64 at a time (a pass without branches),
    // then their sums in the order m_0 fastest, as a loop over every centre adds them.
    const int centres = ipow(r, D);
    PowerSums sum;
    for (int first = 0; first < centres; first += 64)
    {
      const int count = std::min(64, centres - first);
      std::uint64_t near = 0;
      for (int k = 0; k < count; ++k)
      {
        near |= static_cast<std::uint64_t>(std::fabs(phi[first + k]) < this->HalfDiagonal) << k;
      }
      for (; near != 0; near &= near - 1)
      {
        const double dk = d[first + lowestBit(near)];
        sum.First += powAbs(dk, this->P);
        sum.Second += this->Q > 0.0 ? powAbs(dk, this->Q) : 0.0;
        front = true;
      }
    }
    return sum.scaled(this->SubcellWeight);
  }

  const GridField<D, double>& Phi;
  const GridField<D, double>& Distance;
  Q1Interpolator<D> DistanceQ1; // (4.29), 2D
  std::vector<double> Buffers;  // (4.30), 3D: q1AtSubcellCentres's two pairs of buffers
  double P;
  double Q;
  int R;
  double HalfDiagonal = 0.0;
  double SubcellWeight = 0.0;
};

template <int D>
Status checkInputs(const GridField<D, double>& phi, const GridField<D, double>& distance, const EnergyOptions& options)
{
  if (!(options.P >= 1.0) || !std::isfinite(options.P))
  {
    return Status::invalidArgument("the energy exponent p must be finite and >= 1");
  }
  if (options.SecondP != 0.0 && (!(options.SecondP >= 1.0) || !std::isfinite(options.SecondP)))
  {
    return Status::invalidArgument("the second energy exponent must be 0 (none) or finite and >= 1");
  }
  if (options.Refinement < 1)
  {
    return Status::invalidArgument("the subcell refinement R must be >= 1");
  }
  for (int a = 0; a < D; ++a)
  {
    if (phi.spec().Dims[a] != distance.spec().Dims[a] || phi.spec().Spacing[a] != distance.spec().Spacing[a] ||
      phi.spec().Origin[a] != distance.spec().Origin[a])
    {
      return Status::invalidArgument("phi and the distance function must live on the same grid");
    }
    if (phi.spec().Dims[a] < 2)
    {
      return Status::invalidArgument("the energy needs at least two nodes per axis");
    }
  }
  return Status::ok();
}

/// Sums the cells node(j), j in [0, n), over fixed chunks (deterministic for any thread count).
template <int D, class NodeOf>
void sumCells(const GridField<D, double>& phi, const GridField<D, double>& distance, Index n, NodeOf nodeOf,
  const Context& ctx, const EnergyOptions& options, EnergyResult& result)
{
  const Index grain = std::max<Index>(256, (n + 63) / 64);
  const Index chunks = n > 0 ? (n + grain - 1) / grain : 0;
  std::vector<PowerSums> partial(static_cast<size_t>(chunks));
  std::vector<Index> fronts(static_cast<size_t>(chunks), 0);
  const GridSpec<D>& g = phi.spec();
  ctx.parallelFor(
    0, n,
    [&](Index b, Index e)
    {
      CellEnergy<D> energy(phi, distance, options);
      PowerSums sum;
      Index count = 0;
      for (Index j = b; j < e; ++j)
      {
        const std::array<Index, D> cell = phi.nodeIndex(nodeOf(j));
        bool inside = true;
        for (int a = 0; a < D; ++a)
        {
          inside = inside && cell[a] + 1 < g.Dims[a];
        }
        if (!inside)
        {
          continue;
        }
        bool front = false;
        sum += energy(cell, front);
        count += front ? 1 : 0;
      }
      partial[static_cast<size_t>(b / grain)] = sum;
      fronts[static_cast<size_t>(b / grain)] = count;
    },
    grain);
  result = EnergyResult{};
  for (size_t c = 0; c < partial.size(); ++c)
  {
    result.Integral += partial[c].First;
    result.SecondIntegral += partial[c].Second;
    result.FrontCells += fronts[c];
  }
  energiesFromIntegrals(result, options);
}
} // namespace

void energiesFromIntegrals(EnergyResult& result, const EnergyOptions& options)
{
  result.Energy = std::pow(result.Integral, 1.0 / options.P); // (4.29)/(4.30)
  result.SecondEnergy = options.SecondP > 0.0 ? std::pow(result.SecondIntegral, 1.0 / options.SecondP) : 0.0;
}

void reduceEnergy(EnergyResult& local, const EnergyOptions& options, const Communicator& comm)
{
  // One all-reduce: the front cell count is exact as a double (below 2^53).
  double sums[3] = { local.Integral, local.SecondIntegral, static_cast<double>(local.FrontCells) };
  comm.allReduce(sums, 3, ReduceOp::Sum);
  local.Integral = sums[0];
  local.SecondIntegral = sums[1];
  local.FrontCells = static_cast<decltype(local.FrontCells)>(sums[2]);
  energiesFromIntegrals(local, options);
}

template <int D>
Status energyFunctional(const GridField<D, double>& phi, const GridField<D, double>& distance, const Context& ctx,
  EnergyResult& result, const EnergyOptions& options)
{
  SLTK_RETURN_IF_ERROR(checkInputs(phi, distance, options));
  sumCells(
    phi, distance, phi.spec().nodeCount(), [](Index k) { return k; }, ctx, options, result);
  return Status::ok();
}

template <int D>
Status energyFunctional(const GridField<D, double>& phi, const GridField<D, double>& distance, const NodeList& cells,
  const Context& ctx, EnergyResult& result, const EnergyOptions& options)
{
  SLTK_RETURN_IF_ERROR(checkInputs(phi, distance, options));
  const Index nodes = phi.spec().nodeCount();
  for (const Index k : cells)
  {
    if (k < 0 || k >= nodes)
    {
      return Status::invalidArgument("a cell index of the band is outside the grid");
    }
  }
  sumCells(
    phi, distance, static_cast<Index>(cells.size()), [&](Index j) { return cells[static_cast<size_t>(j)]; }, ctx,
    options, result);
  return Status::ok();
}

template Status energyFunctional(
  const GridField<2, double>&, const GridField<2, double>&, const Context&, EnergyResult&, const EnergyOptions&);
template Status energyFunctional(
  const GridField<3, double>&, const GridField<3, double>&, const Context&, EnergyResult&, const EnergyOptions&);
template Status energyFunctional(const GridField<2, double>&, const GridField<2, double>&, const NodeList&,
  const Context&, EnergyResult&, const EnergyOptions&);
template Status energyFunctional(const GridField<3, double>&, const GridField<3, double>&, const NodeList&,
  const Context&, EnergyResult&, const EnergyOptions&);

} // namespace sltk
