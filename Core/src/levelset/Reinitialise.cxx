// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/levelset/Reinitialise.h"

#include "SkewedSteps.h"
#include "sltk/core/ResizeForOverwrite.h"
#include "sltk/exec/ThreadPool.h"
#include "sltk/levelset/ReinitInterface.h"
#include "sltk/levelset/ReinitScheme.h"
#include "sltk/levelset/ReinitStencil.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <string>

// The lanes' helpers and BandSolver::stepLanes are always inlined (into the
// AVX2 function where they take four lanes), so the vector ABI of their
// signatures never applies.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace sltk
{

namespace
{
// Role of a band node, set once from the initial data.
constexpr std::uint8_t RolePde = 0;      // pseudo-time steps of (1.30)
constexpr std::uint8_t RoleRelax = 1;    // Russo-Smereka (1.36) near the front
constexpr std::uint8_t RoleFixed = 2;    // constrained value of X, never changed again
constexpr std::uint8_t RoleKind = 3;     // mask of the three above
constexpr std::uint8_t RoleBoundary = 4; // the 3^D block leaves the interior: ReinitStencil slow path

// Fixed chunk size: the per-chunk maxima are indexed by chunk.
constexpr Index Grain = 2048;
// Band positions between a prefetch and its use in the pseudo-time step.
constexpr Index PrefetchDistance = 16;

/// max that lets a NaN through (so that a blow-up is reported, not hidden).
inline double maxOrNaN(double a, double b)
{
  return b > a || std::isnan(b) ? b : a;
}

/// The largest of `count` changes from `first`, in order (maxOrNaN: a NaN wins).
inline double largestOf(const double* first, Index count)
{
  double change = 0.0;
  for (Index i = 0; i < count; ++i)
  {
    change = maxOrNaN(change, first[i]);
  }
  return change;
}

/// values[offset[l] + shift] for the L band nodes of a group, one per lane.
template <int L>
SLTK_LANES_INLINE lanes::Lanes<L> gatherLanes(const double* values, const Index* offset, Index shift)
{
  lanes::Lanes<L> out;
  lanes::gatherOf<L>([&](int l) { return values[offset[l] + shift]; }, out);
  return out;
}

/// Whether the L band nodes at `offset` are consecutive in storage, in order
/// (any band order is allowed: a group is tested node by node).
template <int L>
SLTK_LANES_INLINE bool consecutive(const Index* offset)
{
  bool all = true;
  for (int l = 1; l < L; ++l)
  {
    all = all && offset[l] == offset[0] + l;
  }
  return all;
}

/// True (all ones) in the lanes whose node has role `kind`.
template <int L>
SLTK_LANES_INLINE lanes::Mask<L> kindLanes(const std::uint8_t* role, std::uint8_t kind)
{
  lanes::Mask<L> out;
  lanes::maskOf<L>([&](int l) { return (role[l] & RoleKind) == kind; }, out);
  return out;
}

/// The band's planes of the slowest axis and their groups (BandSolver::bandPlanes).
struct BandPlanes
{
  std::vector<Index> Start;
  std::vector<Index> Group;
};

/// One reinitialise() call on its band, with the per-node arrays of a
/// ReinitWorkspace (25 bytes a node).
template <int D>
class BandSolver
{
public:
  BandSolver(GridField<D>& phi, const Index* band, Index size, const ReinitOptions& options, const Context& ctx,
    ReinitWorkspace& arrays)
    : Phi(phi)
    , Stencil(phi)
    , Band(band)
    , Size(size)
    , Options(options)
    , Ctx(ctx)
    , Offset(arrays.Offset)
    , Coefficient(arrays.Coefficient)
    , Next(arrays.Next)
    , Role(arrays.Role)
    , ChunkChange(arrays.ChunkChange)
    , Saved(arrays.Saved)
  {
    const GridSpec<D>& g = phi.spec();
    this->H = g.Spacing[0];
    for (int a = 0; a < D; ++a)
    {
      this->Spacing[a] = g.Spacing[a];
      this->InverseSpacing[a] = 1.0 / g.Spacing[a];
      this->H = std::min(this->H, g.Spacing[a]);
    }
    this->Dtau = options.Courant * this->H; // (1.34)
  }

  double spacing() const { return this->H; }

  /// `saving`: also the array of keepBand().
  Status allocate(bool saving)
  {
    try
    {
      // Every entry is written before it is read (classify(), step()): a
      // workspace kept from the last call needs no values, only its pages.
      const size_t n = static_cast<size_t>(this->Size);
      resizeForOverwrite(this->Offset, n);
      resizeForOverwrite(this->Coefficient, n);
      resizeForOverwrite(this->Next, n);
      resizeForOverwrite(this->Role, n);
      resizeForOverwrite(this->ChunkChange, static_cast<size_t>(ThreadPool::chunkCount(0, this->Size, Grain)));
      if (saving)
      {
        resizeForOverwrite(this->Saved, n);
      }
    }
    catch (const std::bad_alloc&)
    {
      return Status::outOfMemory("reinitialisation of a band of " + std::to_string(this->Size) + " nodes");
    }
    return Status::ok();
  }

  /// Reads the initial data phi0 only: role of each node, the sign (1.31) or,
  /// next to the front (1.38), the explicit distance (1.37) / (1.44).
  /// Returns the number of band nodes in X.
  Index classify()
  {
    const double count = this->Ctx.parallelSum(
      0, this->Size,
      [&](Index b, Index e)
      {
        double block[ReinitStencil<D>::BlockSize];
        double near = 0.0;
        for (Index p = b; p < e; ++p)
        {
          near += this->classifyNode(p, block) ? 1.0 : 0.0;
        }
        return near;
      },
      Grain);
    return static_cast<Index>(count);
  }

  /// The one step procedure (Fig. 4.5): X takes its constrained values, once.
  void fixFront()
  {
    double* values = this->Phi.storage().data();
    this->Ctx.parallelFor(
      0, this->Size,
      [&](Index b, Index e)
      {
        for (Index p = b; p < e; ++p)
        {
          if ((this->Role[p] & RoleKind) == RoleFixed)
          {
            values[this->Offset[p]] = this->Coefficient[p];
          }
        }
      },
      Grain);
  }

  /// One Jacobi pseudo-time step over the band; returns the largest |change|.
  double step()
  {
    double* chunkChange = this->ChunkChange.data();
    this->Ctx.parallelFor(
      0, this->Size, [&](Index b, Index e) { chunkChange[b / Grain] = this->stepRange(b, e); }, Grain);
    this->Ctx.parallelFor(
      0, this->Size, [&](Index b, Index e) { this->writeBack(b, e); }, Grain);
    return largestOf(this->ChunkChange.data(), static_cast<Index>(this->ChunkChange.size()));
  }

  /// The band's positions by plane of the slowest axis: plane j (from the band's
  /// first) holds positions Start[j] .. Start[j + 1] - 1, and the planes
  /// Group[g] .. Group[g + 1] - 1 make the g-th group of skewedSteps(). False
  /// when the band is not in ascending order or the slowest axis is periodic (a
  /// step would then read planes at the grid's other end): the skewed steps
  /// need neither.
  bool bandPlanes(BandPlanes& planes) const
  {
    const GridSpec<D>& g = this->Phi.spec();
    if (this->Size == 0 || g.Bounds[D - 1] == Boundary::Periodic)
    {
      return false;
    }
    const Index* band = this->Band;
    const double unordered = this->Ctx.parallelSum(
      1, this->Size,
      [&](Index b, Index e)
      {
        double count = 0.0;
        for (Index p = b; p < e; ++p)
        {
          count += band[p] <= band[p - 1] ? 1.0 : 0.0;
        }
        return count;
      },
      Grain);
    if (unordered > 0.0)
    {
      return false;
    }
    const Index planeNodes = g.nodeCount() / g.Dims[D - 1];
    const Index first = band[0] / planeNodes;
    const Index count = band[this->Size - 1] / planeNodes - first + 1;
    planes.Start.resize(static_cast<size_t>(count + 1));
    for (Index j = 0; j <= count; ++j)
    {
      planes.Start[static_cast<size_t>(j)] = std::lower_bound(band, band + this->Size, (first + j) * planeNodes) - band;
    }
    // Groups of at least detail::SkewedTaskNodes nodes, so that a wave's threads work more than they
    // wait for each other.
    planes.Group.assign(1, 0);
    for (Index z = 1; z <= count; ++z)
    {
      if (z == count || planes.Start[z] - planes.Start[planes.Group.back()] >= detail::SkewedTaskNodes)
      {
        planes.Group.push_back(z);
      }
    }
    return true;
  }

  /// `steps` Jacobi steps, the values of step() called `steps` times bit for
  /// bit, step t's largest |change| into changes[t]; in the skewed waves of
  /// SkewedSteps.h over the groups of planes of bandPlanes(), so that the steps
  /// share each plane's trip through the caches.
  void skewedSteps(const BandPlanes& planes, Index steps, double* changes)
  {
    const std::vector<Index>& start = planes.Start;
    const std::vector<Index>& group = planes.Group;
    const Index last = static_cast<Index>(start.size()) - 1; // one past the last plane
    const Index groups = static_cast<Index>(group.size()) - 1;
    std::vector<double> groupChange(static_cast<size_t>(steps * groups));
    detail::skewedWaves(groups, steps, this->Ctx,
      [&](Index t, Index g)
      {
        double change = 0.0;
        const Index stop = g < groups ? group[g + 1] : last + 1;
        for (Index z = group[g]; z < stop; ++z)
        {
          if (z < last)
          {
            change = maxOrNaN(change, this->stepRange(start[z], start[z + 1]));
          }
          if (z > 0)
          {
            this->writeBack(start[z - 1], start[z]);
          }
        }
        if (g < groups)
        {
          groupChange[static_cast<size_t>(t * groups + g)] = change;
        }
      });
    for (Index t = 0; t < steps; ++t)
    {
      changes[t] = largestOf(groupChange.data() + t * groups, groups);
    }
  }

  /// Keeps the band's values (`keep`: before skewed steps that may overshoot a
  /// stop) or puts the kept ones back.
  void keepBand(bool keep)
  {
    double* values = this->Phi.storage().data();
    this->Ctx.parallelFor(
      0, this->Size,
      [&](Index b, Index e)
      {
        for (Index p = b; p < e; ++p)
        {
          double& value = values[this->Offset[p]];
          if (keep)
          {
            this->Saved[p] = value;
          }
          else
          {
            value = this->Saved[p];
          }
        }
      },
      Grain);
  }

private:
  /// The step of band positions [b, e) into Next; returns their largest |change|.
  double stepRange(Index b, Index e)
  {
    double change = 0.0;
    Index p = b;
#if defined(SLTK_LANES_AVX2)
    p = lanes::hasAvx2() ? this->stepLanesAvx2(b, e, change) : this->stepLanes<2>(b, e, change);
#else
    p = this->stepLanes<2>(b, e, change);
#endif
    for (; p < e; ++p)
    {
      this->stepNode(p, change);
    }
    return change;
  }

  /// Next back into phi on band positions [b, e) (a fixed node keeps its value).
  void writeBack(Index b, Index e)
  {
    double* values = this->Phi.storage().data();
    const Index* offset = this->Offset.data();
    const std::uint8_t* role = this->Role.data();
    const double* next = this->Next.data();
    for (Index p = b; p < e; ++p)
    {
      if ((role[p] & RoleKind) != RoleFixed)
      {
        values[offset[p]] = next[p];
      }
    }
  }

  bool classifyNode(Index p, double* block)
  {
    const std::array<Index, D> i = this->Stencil.node(this->Band[p]);
    this->Offset[p] = this->Phi.offset(i);
    const bool interior = this->Stencil.interior(i);
    const std::uint8_t boundary = interior ? 0 : RoleBoundary;
    // The axis neighbours decide (1.38) and give (1.31); only the front's nodes
    // need the whole 3^D block, so an interior node away from it reads 1 + 2D values.
    // (Beyond the grid the block extrapolates, as (1.37) and (1.44) read it.)
    double u[ReinitStencil<D>::AxisSize];
    if (interior)
    {
      this->Stencil.axesInterior(this->Phi.storage().data() + this->Offset[p], u);
    }
    else
    {
      this->Stencil.block(i, block);
      axesOfBlock<D>(block, u);
    }
    const bool near = axesAdjacentToInterface<D>(u); // (1.38)
    if (!near || this->Options.Method == ReinitMethod::Plain)
    {
      this->Role[p] = RolePde | boundary;
      this->Coefficient[p] = reinitSign(u[0], axesCentralGradientNorm<D>(u, this->InverseSpacing), this->H); // (1.31)
      return near;
    }
    if (interior)
    {
      this->Stencil.blockInterior(this->Phi.storage().data() + this->Offset[p], block);
    }
    if (this->Options.Method == ReinitMethod::Constrained)
    {
      this->Role[p] = RoleFixed | boundary;
      this->Coefficient[p] = constrainedDistance<D>(this->Stencil, i, block, this->InverseSpacing, this->Spacing);
    }
    else // ReinitMethod::RussoSmereka
    {
      this->Role[p] = RoleRelax | boundary;
      this->Coefficient[p] = interfaceDistance<D>(block, this->InverseSpacing, this->Spacing); // (1.37)
    }
    return near;
  }

  /// The pseudo-time step of band node p into Next[p], its |change| into `change`.
  void stepNode(Index p, double& change)
  {
    const std::uint8_t kind = this->Role[p] & RoleKind;
    if (kind == RoleFixed)
    {
      return;
    }
    double u[ReinitStencil<D>::AxisSize];
    if (this->Role[p] & RoleBoundary)
    {
      this->Stencil.axes(this->Stencil.node(this->Band[p]), u);
    }
    else
    {
      this->Stencil.axesInterior(this->Phi.storage().data() + this->Offset[p], u);
    }
    const double c = this->Coefficient[p];
    const double v = kind == RolePde
      ? reinitStep<D>(this->Options.Scheme, u, this->InverseSpacing, c, this->Dtau) // (1.32)/(1.35)
      : russoSmerekaStep(u[0], c, this->Options.Courant);                           // (1.36)
    this->Next[p] = v;
    change = maxOrNaN(change, std::fabs(v - u[0]));
  }

  /// stepNode() for the band nodes [b, e) L at a time, one per lane (Lanes.h;
  /// the same values bit for bit: the schemes are templates of ReinitScheme.h),
  /// a group with a node next to the grid's end node by node; returns where
  /// the groups stopped.
  template <int L>
  SLTK_LANES_INLINE Index stepLanes(Index b, Index e, double& change)
  {
    using Vec = lanes::Lanes<L>;
    using Mask = lanes::Mask<L>;
    const double* values = this->Phi.storage().data();
    const auto& strides = this->Phi.strides();
    const Index* offset = this->Offset.data();
    const std::uint8_t* role = this->Role.data();
    const bool relaxing = this->Options.Method == ReinitMethod::RussoSmereka;
    Vec largest{};
    Index p = b;
    for (; p + L <= e; p += L)
    {
      std::uint8_t boundary = 0;
      for (int l = 0; l < L; ++l)
      {
#if defined(__GNUC__)
        // The upper neighbour along the slowest axis is the first touch of its
        // cache line: fetch it ahead (the loop is bound by these misses).
        if (p + l + PrefetchDistance < e)
        {
          __builtin_prefetch(values + offset[p + l + PrefetchDistance] + strides[D - 1]);
        }
#endif
        boundary |= role[p + l] & RoleBoundary;
      }
      if (boundary)
      {
        for (int l = 0; l < L; ++l)
        {
          this->stepNode(p + l, change);
        }
        continue;
      }
      Vec u[ReinitStencil<D>::AxisSize];
      if (consecutive<L>(offset + p)) // L nodes of an x line in a row: plain loads
      {
        const double* at = values + offset[p];
        lanes::loadOf<L>(at, u[0]);
        for (int a = 0; a < D; ++a)
        {
          lanes::loadOf<L>(at - strides[a], u[1 + 2 * a]);
          lanes::loadOf<L>(at + strides[a], u[2 + 2 * a]);
        }
      }
      else
      {
        u[0] = gatherLanes<L>(values, offset + p, 0);
        for (int a = 0; a < D; ++a)
        {
          u[1 + 2 * a] = gatherLanes<L>(values, offset + p, -strides[a]);
          u[2 + 2 * a] = gatherLanes<L>(values, offset + p, strides[a]);
        }
      }
      Vec c;
      std::memcpy(&c, this->Coefficient.data() + p, sizeof(Vec));
      const Mask relax = relaxing ? kindLanes<L>(role + p, RoleRelax) : Mask{};
      Vec v; // (1.32)/(1.35), or (1.36) in the lanes of `relax`
      bandNodeStep<D>(this->Options.Scheme, u, this->InverseSpacing, c, this->Dtau, this->Options.Courant,
        relaxing ? &relax : nullptr, v);
      std::memcpy(this->Next.data() + p, &v, sizeof(Vec)); // a fixed node's is never copied back
      Vec moved;
      lanes::absOf(v - u[0], moved);
      moved = kindLanes<L>(role + p, RoleFixed) ? Vec{} : moved;
      const Mask larger = (moved > largest) | (moved != moved); // maxOrNaN
      largest = larger ? moved : largest;
    }
    double each[L];
    std::memcpy(each, &largest, sizeof(Vec));
    for (int l = 0; l < L; ++l)
    {
      change = maxOrNaN(change, each[l]);
    }
    return p;
  }

#if defined(SLTK_LANES_AVX2)
  SLTK_LANES_AVX2_TARGET Index stepLanesAvx2(Index b, Index e, double& change)
  {
    return this->stepLanes<4>(b, e, change);
  }
#endif

  GridField<D>& Phi;
  const ReinitStencil<D> Stencil;
  const Index* Band;
  Index Size;
  const ReinitOptions& Options;
  const Context& Ctx;
  double Spacing[D];
  double InverseSpacing[D];
  double H = 0.0;    // smallest spacing: the dx of (1.31), (1.34)
  double Dtau = 0.0; // pseudo-time step

  // The workspace's arrays (ReinitWorkspace), sized by allocate().
  std::vector<Index>& Offset;
  std::vector<double>& Coefficient; // s of (1.31) for RolePde, the target distance otherwise
  std::vector<double>& Next;
  std::vector<std::uint8_t>& Role; // Role* flags
  std::vector<double>& ChunkChange;
  std::vector<double>& Saved; // the band's values before skewed steps
};

Status validateBand(const Index* band, Index size, Index nodes, const Context& ctx)
{
  if (size < 0 || (size > 0 && !band))
  {
    return Status::invalidArgument("reinitialisation band: null pointer or negative size");
  }
  const double outside = ctx.parallelSum(
    0, size,
    [&](Index b, Index e)
    {
      double bad = 0.0;
      for (Index p = b; p < e; ++p)
      {
        bad += (band[p] < 0 || band[p] >= nodes) ? 1.0 : 0.0;
      }
      return bad;
    },
    Grain);
  if (outside > 0.0)
  {
    return Status::invalidArgument("reinitialisation band holds " + std::to_string(static_cast<Index>(outside)) +
      " indices outside [0, " + std::to_string(nodes) + ")");
  }
  return Status::ok();
}
} // namespace

template <int D>
Status reinitialise(GridField<D>& phi, const Index* band, Index bandSize, const ReinitOptions& options,
  const Context& ctx, ReinitReport* report, const ReinitStepExchange& exchange, ReinitWorkspace* workspace)
{
  ReinitReport result;
  auto finish = [&](Status status)
  {
    if (report)
    {
      *report = result;
    }
    return status;
  };
  Status ready = phi.spec().validate();
  ready = ready.isOk() ? options.template validate<D>() : ready;
  ready = ready.isOk() ? validateBand(band, bandSize, phi.spec().nodeCount(), ctx) : ready;
  const bool distributed = static_cast<bool>(exchange.AfterStep);
  if (!ready.isOk())
  {
    return finish(exchange.Agree ? exchange.Agree(ready) : ready); // every rank makes one Agree call
  }
  if (bandSize == 0 && !distributed)
  {
    result.Converged = true;
    return finish(Status::ok());
  }
  ReinitWorkspace own;
  ReinitWorkspace& arrays = workspace ? *workspace : own;
  BandSolver<D> solver(phi, band, bandSize, options, ctx, arrays);
  // One process and a band larger than the caches: the steps go in skewed rounds
  // (SkewedSteps.h), each round's band kept first in case a stop falls within it.
  // Distributed, every step exchanges ghost rows.
  const bool skewable =
    !distributed && options.MaxIterations >= detail::MinimumSkewedRound && bandSize >= arrays.SkewedBandNodes;
  BandPlanes planes;
  const bool skewed = skewable && solver.bandPlanes(planes);
  const Status allocated = solver.allocate(skewed);
  SLTK_RETURN_IF_ERROR(finish(exchange.Agree ? exchange.Agree(allocated) : allocated));
  result.InterfaceNodes = solver.classify();
  if (options.Method == ReinitMethod::Constrained)
  {
    solver.fixFront();
  }
  if (distributed)
  {
    bool ignored = false;
    exchange.AfterStep(0.0, ignored); // the front's fixed values (1.37)/(1.44) reach the neighbours' ghost rows
  }

  Interrupter& interrupter = ctx.interrupter();
  const double tolerance = options.Tolerance * solver.spacing();
  result.Converged = options.MaxIterations == 0;
  double changes[detail::MaximumSkewedRound];
  double before = 0.0, latest = 0.0; // the last two steps' largest changes
  int done = 0;
  while (done < options.MaxIterations)
  {
    const int round = skewed ? detail::skewedRound(before, latest, options.MaxIterations - done, tolerance) : 1;
    if (round > 1)
    {
      solver.keepBand(true);
      solver.skewedSteps(planes, round, changes);
    }
    else
    {
      changes[0] = solver.step();
    }
    // A stop at the round's step j: phi goes back to that step's values.
    const auto stopAt = [&](int j)
    {
      if (j + 1 < round)
      {
        solver.keepBand(false);
        for (int k = 0; k <= j; ++k)
        {
          solver.step();
        }
      }
    };
    for (int j = 0; j < round; ++j)
    {
      const int iteration = done + j + 1;
      result.MaxChange = changes[j];
      result.Iterations = iteration;
      before = latest;
      latest = changes[j];
      bool interrupted = false;
      if (distributed)
      {
        // Every rank takes the same decisions below: the largest change over the ranks, a stop on any rank.
        interrupted = interrupter.wasInterrupted(static_cast<double>(iteration) / options.MaxIterations);
        result.MaxChange = exchange.AfterStep(result.MaxChange, interrupted);
      }
      if (!std::isfinite(result.MaxChange))
      {
        stopAt(j);
        return finish(Status::numericalFailure("reinitialisation produced a non-finite value at pseudo-time step " +
          std::to_string(iteration) + " (is the level-set function finite in and around the band?)"));
      }
      if (result.MaxChange < tolerance)
      {
        stopAt(j);
        result.Converged = true;
        return finish(Status::ok());
      }
      const bool last = j + 1 == round;
      if (last &&
        (distributed ? interrupted
                     : interrupter.wasInterrupted(static_cast<double>(iteration) / options.MaxIterations)))
      {
        return finish(Status::aborted());
      }
    }
    done += round;
  }
  return finish(Status::ok());
}

template Status reinitialise(GridField<2>&, const Index*, Index, const ReinitOptions&, const Context&, ReinitReport*,
  const ReinitStepExchange&, ReinitWorkspace*);
template Status reinitialise(GridField<3>&, const Index*, Index, const ReinitOptions&, const Context&, ReinitReport*,
  const ReinitStepExchange&, ReinitWorkspace*);

} // namespace sltk
