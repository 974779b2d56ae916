// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/FastSweeping.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

namespace sltk
{

namespace
{
/// The Godunov update with precomputed spacings h and weights w = 1 / h^2.
inline double godunovUpdate(const double* a, const double* h, const double* w, int dims)
{
  // Sort the neighbour values ascending (dims <= 3), carrying the spacings.
  double v[3] = { a[0], 0.0, 0.0 };
  double hs[3] = { h[0], 0.0, 0.0 };
  double ws[3] = { w[0], 0.0, 0.0 };
  for (int k = 1; k < dims; ++k)
  {
    int m = k;
    for (; m > 0 && a[k] < v[m - 1]; --m)
    {
      v[m] = v[m - 1];
      hs[m] = hs[m - 1];
      ws[m] = ws[m - 1];
    }
    v[m] = a[k];
    hs[m] = h[k];
    ws[m] = w[k];
  }
  if (!(v[0] < std::numeric_limits<double>::infinity()))
  {
    return std::numeric_limits<double>::infinity();
  }
  // One axis: u = a_0 + h_0; add axes while the solution exceeds the next value.
  double u = v[0] + hs[0];
  double sw = ws[0];
  double swa = ws[0] * v[0];
  double swa2 = ws[0] * v[0] * v[0];
  for (int m = 1; m < dims; ++m)
  {
    if (u <= v[m])
    {
      break;
    }
    // sum_k w_k (u - v_k)^2 = 1 over the first m + 1 axes.
    sw += ws[m];
    swa += ws[m] * v[m];
    swa2 += ws[m] * v[m] * v[m];
    const double disc = swa * swa - sw * (swa2 - 1.0);
    u = (swa + std::sqrt(std::max(0.0, disc))) / sw;
  }
  return u;
}
} // namespace

namespace
{
/// godunovUpdate() when every axis has the spacing h (w = 1 / h^2), bit for
/// bit for values that are not NaN (the sweeps hold distances and +infinity;
/// std::min would drop a NaN that godunovUpdate() passes on; Profile.md, "The
/// automatic K_P's probe"): the values sorted by a min/max network (equal
/// values are interchangeable when the spacings are), and the two- and
/// three-axis solutions computed side by side, by godunovUpdate()'s
/// expressions in its order, then chosen by its tests. In the sweeps a node's
/// update waits for its x neighbour's, so the time of one update is the
/// length of this chain: one square root and one division instead of two of
/// each after a sort's mispredicted branches.
template <int Dims>
inline double godunovUniform(const double* a, double h, double w)
{
  const double inf = std::numeric_limits<double>::infinity();
  double v0 = a[0], v1 = inf, v2 = inf;
  if constexpr (Dims == 2)
  {
    v0 = std::min(a[0], a[1]);
    v1 = std::max(a[0], a[1]);
  }
  else if constexpr (Dims == 3)
  {
    const double low = std::min(a[0], a[1]), high = std::max(a[0], a[1]);
    v0 = std::min(low, a[2]);
    const double middle = std::max(low, a[2]);
    v1 = std::min(high, middle);
    v2 = std::max(high, middle);
  }
  if (!(v0 < inf))
  {
    return inf;
  }
  const double one = v0 + h;
  if constexpr (Dims == 1)
  {
    return one;
  }
  const double sw1 = w + w;
  const double swa1 = w * v0 + w * v1;
  const double swa21 = w * v0 * v0 + w * v1 * v1;
  const double two = (swa1 + std::sqrt(std::max(0.0, swa1 * swa1 - sw1 * (swa21 - 1.0)))) / sw1;
  double three = two;
  if constexpr (Dims == 3)
  {
    const double sw2 = sw1 + w;
    const double swa2 = swa1 + w * v2;
    const double swa22 = swa21 + w * v2 * v2;
    three = (swa2 + std::sqrt(std::max(0.0, swa2 * swa2 - sw2 * (swa22 - 1.0)))) / sw2;
  }
  return one <= v1 ? one : (Dims == 2 || two <= v2 ? two : three);
}
} // namespace

double godunovEikonalUniform(const double* a, double h, int dims)
{
  const double w = 1.0 / (h * h);
  return dims == 1 ? godunovUniform<1>(a, h, w) : dims == 2 ? godunovUniform<2>(a, h, w) : godunovUniform<3>(a, h, w);
}

double godunovEikonal(const double* a, const double* h, int dims)
{
  double w[3] = { 1.0, 1.0, 1.0 };
  for (int k = 0; k < dims; ++k)
  {
    w[k] = 1.0 / (h[k] * h[k]);
  }
  return godunovUpdate(a, h, w, dims);
}

namespace
{
/// One Gauss-Seidel sweep of a 3D (or one-layer 2D) grid in one of the 2^D
/// orders, with the locks of Bak, McLaughlin and Renzi (2010): a node is
/// recomputed only when a neighbour changed since its last update. Skipped
/// updates would reproduce the value already applied, so the result is that
/// of the plain method.
template <int D>
struct Sweeper
{
  Index N[3] = { 1, 1, 1 };      ///< nodes per axis (2D: one layer along z)
  Index Stride[3] = { 0, 0, 0 }; ///< storage strides
  Index NodeStep[3] = { 1, 1, 1 };
  double H[3] = { 1.0, 1.0, 1.0 };
  double W[3] = { 1.0, 1.0, 1.0 }; ///< 1 / h^2
  bool Uniform = false;            ///< every axis has the spacing H[0]: godunovUniform()
  double* U = nullptr;
  const std::uint8_t* Frozen = nullptr;
  /// The locks, relaxed atomics: with two threads on neighbouring planes both may
  /// unlock one node (to the same value).
  std::unique_ptr<std::atomic<std::uint8_t>[]> Live;
  /// The x lines swept together, each a node behind the previous (lines()).
  static constexpr Index LineGroup = 4;

  void unlock(Index node) const { this->Live[node].store(!this->Frozen[node], std::memory_order_relaxed); }

  /// Node i of the x line j of plane k (storage row `row`, node index
  /// `lineNode` of its first node): unless locked, the Godunov update, applied
  /// when it decreases the value, which unlocks the axis neighbours.
  void visit(Index i, Index j, Index k, double* row, Index lineNode, double& change) const
  {
    const double inf = std::numeric_limits<double>::infinity();
    const Index node = lineNode + i;
    if (!this->Live[node].load(std::memory_order_relaxed))
    {
      return;
    }
    this->Live[node].store(0, std::memory_order_relaxed);
    double* q = row + i * this->Stride[0];
    const Index idx[3] = { i, j, k };
    double nb[3] = { inf, inf, inf };
    for (int a = 0; a < D; ++a)
    {
      const double lo = idx[a] > 0 ? q[-this->Stride[a]] : inf;
      const double hi = idx[a] < this->N[a] - 1 ? q[this->Stride[a]] : inf;
      nb[a] = std::min(lo, hi);
    }
    const double v =
      this->Uniform ? godunovUniform<D>(nb, this->H[0], this->W[0]) : godunovUpdate(nb, this->H, this->W, D);
    if (v < *q)
    {
      change = std::max(change, std::isfinite(*q) ? *q - v : inf);
      *q = v;
      for (int a = 0; a < D; ++a)
      {
        if (idx[a] > 0)
        {
          this->unlock(node - this->NodeStep[a]);
        }
        if (idx[a] < this->N[a] - 1)
        {
          this->unlock(node + this->NodeStep[a]);
        }
      }
    }
  }

  /// The x lines jj .. jj + count - 1 (count <= LineGroup) of sweep-order plane
  /// kk in sweep order `back`, each one node behind the previous: at step t,
  /// node t - g of line jj + g. Every pair of axis neighbours is visited in the
  /// serial order (along x as in a line; (i, j) one step before (i, j + 1)), so
  /// each node reads the values and locks the serial sweep shows it, bit for
  /// bit; but the nodes of a step do not wait for one another, so their
  /// updates (a chain of a square root and a division each, behind the x
  /// neighbour's) overlap. Returns the largest decrease.
  double lines(const bool* back, Index kk, Index jj, Index count) const
  {
    const Index k = back[2] ? this->N[2] - 1 - kk : kk;
    double* row[LineGroup];
    Index lineNode[LineGroup], j[LineGroup];
    for (Index g = 0; g < count; ++g)
    {
      j[g] = back[1] ? this->N[1] - 1 - (jj + g) : jj + g;
      lineNode[g] = this->N[0] * (j[g] + this->N[1] * k);
      row[g] = this->U + j[g] * this->Stride[1] + k * this->Stride[2];
    }
    double change = 0.0;
    const Index n = this->N[0];
    for (Index t = 0; t < n + count - 1; ++t)
    {
      for (Index g = std::max<Index>(0, t - n + 1); g < std::min(count, t + 1); ++g)
      {
        const Index ii = t - g;
        this->visit(back[0] ? n - 1 - ii : ii, j[g], k, row[g], lineNode[g], change);
      }
    }
    return change;
  }

  double serialSweep(const bool* back) const
  {
    double change = 0.0;
    for (Index kk = 0; kk < this->N[2]; ++kk)
    {
      for (Index jj = 0; jj < this->N[1]; jj += LineGroup)
      {
        change = std::max(change, this->lines(back, kk, jj, std::min(LineGroup, this->N[1] - jj)));
      }
    }
    return change;
  }

  /// The same sweep on two threads, bit for bit: thread t takes the planes
  /// kk = t, t + 2, ... of the sweep order, and line j of plane kk starts once
  /// line j of plane kk - 1 is done. Each node then reads the neighbours the
  /// serial order shows it: plane kk - 1's line j already swept, plane kk + 1's
  /// not yet (its line j waits for this one), and its own plane's lines in order.
  double pipelinedSweep(const bool* back, const Context& ctx) const
  {
    // One cache line per plane's counter, published every few lines: a line whose
    // nodes are locked takes less time than a cache line's trip between cores.
    constexpr Index PublishEvery = 8;
    static_assert(PublishEvery % LineGroup == 0, "a group of lines must end where progress is published");
    struct alignas(64) Progress
    {
      std::atomic<Index> LinesDone{ 0 };
    };
    std::unique_ptr<Progress[]> planes(new Progress[static_cast<size_t>(this->N[2])]);
    double change[2] = { 0.0, 0.0 };
    ctx.parallelFor(
      0, 2,
      [&](Index first, Index)
      {
        for (Index kk = first; kk < this->N[2]; kk += 2)
        {
          Index seen = kk > 0 ? 0 : this->N[1]; // lines of plane kk - 1 known to be done
          for (Index jj = 0; jj < this->N[1]; jj += LineGroup)
          {
            const Index count = std::min(LineGroup, this->N[1] - jj);
            for (int spin = 0; seen < jj + count; ++spin)
            {
              seen = planes[kk - 1].LinesDone.load(std::memory_order_acquire);
              if (spin > 64)
              {
                std::this_thread::yield(); // the other thread may share this core (oversubscribed ranks)
              }
            }
            change[first] = std::max(change[first], this->lines(back, kk, jj, count));
            if ((jj + count) % PublishEvery == 0 || jj + count == this->N[1])
            {
              planes[kk].LinesDone.store(jj + count, std::memory_order_release);
            }
          }
        }
      },
      1);
    return std::max(change[0], change[1]);
  }
};
} // namespace

template <int D>
Status fastSweep(GridField<D, double>& u, const std::vector<std::uint8_t>& frozen, const Context& ctx,
  const FastSweepingOptions& options, FastSweepingReport* report)
{
  const GridSpec<D>& g = u.spec();
  if (static_cast<Index>(frozen.size()) != g.nodeCount())
  {
    return Status::invalidArgument("fast sweeping: the frozen mask must have one entry per grid node");
  }
  // Treat 2D as 3D with one layer: n = 1 and no neighbours along z.
  Sweeper<D> sweeper;
  double minH = std::numeric_limits<double>::infinity();
  for (int a = 0; a < D; ++a)
  {
    sweeper.N[a] = g.Dims[a];
    sweeper.Stride[a] = u.strides()[a];
    sweeper.H[a] = g.Spacing[a];
    sweeper.W[a] = 1.0 / (sweeper.H[a] * sweeper.H[a]);
    minH = std::min(minH, sweeper.H[a]);
  }
  sweeper.Uniform = std::all_of(sweeper.H, sweeper.H + D, [&](double h) { return h == sweeper.H[0]; });
  sweeper.NodeStep[1] = sweeper.N[0];
  sweeper.NodeStep[2] = sweeper.N[0] * sweeper.N[1];
  sweeper.U = u.origin();
  sweeper.Frozen = frozen.data();
  sweeper.Live.reset(new std::atomic<std::uint8_t>[frozen.size()]);
  for (size_t k = 0; k < frozen.size(); ++k)
  {
    sweeper.Live[k].store(frozen[k] ? 0 : 1, std::memory_order_relaxed);
  }
  // Two threads only when two run at once (a pool with a worker) and there are planes to share.
  const bool pipelined = ctx.Executor && ctx.Executor->size() >= 2 && sweeper.N[2] >= 2;
  const double tolerance = options.Tolerance * minH;
  FastSweepingReport local;
  for (int cycle = 0; cycle < options.MaxCycles; ++cycle)
  {
    double change = 0.0;
    for (int order = 0; order < (1 << D); ++order)
    {
      const bool back[3] = { (order & 1) != 0, (order & 2) != 0, (order & 4) != 0 };
      change = std::max(change, pipelined ? sweeper.pipelinedSweep(back, ctx) : sweeper.serialSweep(back));
    }
    local.Cycles = cycle + 1;
    local.LastChange = change;
    if (change <= tolerance)
    {
      local.Converged = true;
      break;
    }
    if (ctx.interrupter().wasInterrupted())
    {
      if (report)
      {
        *report = local;
      }
      return Status::aborted();
    }
  }
  if (report)
  {
    *report = local;
  }
  return Status::ok();
}

template Status fastSweep(GridField<2, double>&, const std::vector<std::uint8_t>&, const Context&,
  const FastSweepingOptions&, FastSweepingReport*);
template Status fastSweep(GridField<3, double>&, const std::vector<std::uint8_t>&, const Context&,
  const FastSweepingOptions&, FastSweepingReport*);

} // namespace sltk
