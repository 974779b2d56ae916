// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/tiled/TiledReconstruction.h"

#include "TiledReinitialise.h"
#include "sltk/exec/Memory.h"
#include "sltk/interp/Interpolators.h"
#include "sltk/levelset/ReinitInterface.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/StoppingRule.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace sltk
{

namespace
{
constexpr int Ghost = 2;              ///< ghost layers of the scratch fields (WENO3 / CWENO stencils)
constexpr int StencilReach = 2;       ///< nodes beyond a foot's cell the interpolators read
constexpr int HaloStep = 4;           ///< the step's halo is a multiple of this (fewer scratch shapes)
constexpr int MaxHalo = 4 * TileEdge; ///< the farthest the step reads around a tile

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Index in the scratch block (tile and `halo` nodes around it) of node `local` of the tile.
template <int D>
Index scratchNode(Index local, Index halo)
{
  const Index edge = TileEdge + 2 * halo;
  Index k = 0, stride = 1;
  for (int a = 0; a < D; ++a)
  {
    k += (halo + ((local >> (TileBits * a)) & (TileEdge - 1))) * stride;
    stride *= edge;
  }
  return k;
}

/// Q1 of a tiled field at x (unit-box units).
template <int D>
double tiledQ1(const TiledField<D>& f, const std::array<double, D>& x)
{
  const GridSpec<D>& g = f.grid();
  std::array<Index, D> cell{};
  double w[D];
  for (int a = 0; a < D; ++a)
  {
    const double u = (x[a] - g.Origin[a]) / g.Spacing[a];
    const double c = std::floor(u);
    cell[a] = static_cast<Index>(c);
    w[a] = u - c;
  }
  double sum = 0.0;
  for (int corner = 0; corner < (1 << D); ++corner)
  {
    std::array<Index, D> i = cell;
    double weight = 1.0;
    for (int a = 0; a < D; ++a)
    {
      const bool up = (corner >> a) & 1;
      i[a] += up ? 1 : 0;
      weight *= up ? w[a] : 1.0 - w[a];
    }
    sum += weight * f.value(i);
  }
  return sum;
}

/// The previous run's phi: run 1's uniform field or a tiled one.
template <int D>
struct PreviousLevelSet
{
  const GridField<D>* Dense = nullptr;
  const TiledField<D>* Tiled = nullptr;

  double at(const std::array<double, D>& x) const
  {
    if (this->Tiled)
    {
      return tiledQ1<D>(*this->Tiled, x);
    }
    Q1Interpolator<D> interp(*this->Dense);
    return interpolate(interp, this->Dense->spec(), x.data());
  }

  /// Calls f(x) at every node of the previous band (|phi| < gamma).
  template <class F>
  void forEachBandNode(double gamma, F&& f) const
  {
    if (this->Tiled)
    {
      const TiledField<D>& t = *this->Tiled;
      for (std::int32_t id = 0; id < t.tileCount(); ++id)
      {
        const double* p = t.phi(id);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (std::fabs(p[k]) < gamma)
          {
            f(t.position(t.node(id, k)));
          }
        }
      }
      return;
    }
    const GridSpec<D>& g = this->Dense->spec();
    for (Index k = 0; k < g.nodeCount(); ++k)
    {
      const auto i = this->Dense->nodeIndex(k);
      if (std::fabs((*this->Dense)(i)) < gamma)
      {
        std::array<double, D> x{};
        for (int a = 0; a < D; ++a)
        {
          x[a] = g.coordinate(a, i[a]);
        }
        f(x);
      }
    }
  }
};

/// Grid index of the node nearest to x.
template <int D>
std::array<Index, D> nearestNode(const GridSpec<D>& g, const std::array<double, D>& x)
{
  std::array<Index, D> i{};
  for (int a = 0; a < D; ++a)
  {
    i[a] = static_cast<Index>(std::lround((x[a] - g.Origin[a]) / g.Spacing[a]));
  }
  return i;
}

/// Calls f(slot) for the slots of the 3^D tiles around tile coordinates t (inside the slot grid).
template <int D, class F>
void forEachSlotAround(const TiledField<D>& field, const std::array<Index, D>& t, F&& f)
{
  constexpr int Count = D == 2 ? 9 : 27;
  for (int n = 0; n < Count; ++n)
  {
    std::array<Index, D> s{};
    bool inside = true;
    int rest = n;
    for (int a = 0; a < D; ++a)
    {
      s[a] = t[a] + rest % 3 - 1;
      rest /= 3;
      inside = inside && s[a] >= 0 && s[a] < field.slotDims()[a];
    }
    if (inside)
    {
      f(field.slotIndex(s));
    }
  }
}

/// The memory of `tiles` more tiles, refused when it does not fit.
template <int D>
Status checkTileMemory(const TiledField<D>& field, Index tiles, const ReconstructionOptions& options, int run)
{
  const double need = field.bytes() + static_cast<double>(tiles) * TiledField<D>::Nodes * 2.0 * sizeof(double);
  const double available = static_cast<double>(options.MemoryBudget ? options.MemoryBudget : availableMemoryBytes());
  if (available > 0.0 && need > available)
  {
    std::ostringstream m;
    m.precision(3);
    m << "run " << run << " of the tiled reconstruction needs " << need / 1048576.0 << " MB for "
      << field.tileCount() + tiles << " tiles, more than the " << available / 1048576.0
      << " MB available: use fewer runs or a larger C_dx";
    return Status::outOfMemory(m.str());
  }
  return Status::ok();
}

/// Exact distances to the cloud at the nodes of tiles [first, tileCount()).
template <int D>
void exactDistances(TiledField<D>& field, std::int32_t first, const PointLocator<D>& locator, const Context& ctx)
{
  ctx.parallelFor(
    first, field.tileCount(),
    [&](Index b, Index e)
    {
      for (Index id = b; id < e; ++id)
      {
        const auto tile = static_cast<std::int32_t>(id);
        double* d = field.distance(tile);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          d[k] = locator.nearest(field.position(field.node(tile, k))).Distance;
        }
      }
    },
    1);
}

/// Run r's field from run r-1's level set: tiles within one tile of its band,
/// phi by Q1 cut at +-gamma, d exact; every other slot the side of its centre.
template <int D>
Status transferToTiles(const PreviousLevelSet<D>& previous, double previousGamma, const GridSpec<D>& grid,
  const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field)
{
  const double gamma = plan.Options.GammaFactor * grid.Spacing[0];
  field.reset(grid, gamma);
  std::vector<std::uint8_t> marked(static_cast<size_t>(field.slotCount()), 0);
  previous.forEachBandNode(previousGamma,
    [&](const std::array<double, D>& x)
    {
      std::array<Index, D> t = nearestNode<D>(grid, x);
      for (int a = 0; a < D; ++a)
      {
        t[a] = std::min(std::max<Index>(t[a] >> TileBits, 0), field.slotDims()[a] - 1);
      }
      forEachSlotAround<D>(field, t, [&](Index s) { marked[static_cast<size_t>(s)] = 1; });
    });
  Index count = 0;
  for (std::uint8_t m : marked)
  {
    count += m;
  }
  SLTK_RETURN_IF_ERROR(checkTileMemory(field, count, plan.Options, run));
  // Sides of the slots without tiles: the sign of the previous phi at their centre.
  ctx.parallelFor(0, field.slotCount(),
    [&](Index b, Index e)
    {
      for (Index s = b; s < e; ++s)
      {
        if (!marked[static_cast<size_t>(s)])
        {
          const auto t = field.slotCoordinates(s);
          std::array<double, D> x{};
          for (int a = 0; a < D; ++a)
          {
            x[a] = grid.Origin[a] + (static_cast<double>(t[a] * TileEdge) + 0.5 * (TileEdge - 1)) * grid.Spacing[a];
          }
          field.setSide(s, previous.at(x) < 0.0);
        }
      }
    });
  for (Index s = 0; s < field.slotCount(); ++s)
  {
    if (marked[static_cast<size_t>(s)])
    {
      field.addTile(s);
    }
  }
  ctx.parallelFor(
    0, field.tileCount(),
    [&](Index b, Index e)
    {
      for (Index id = b; id < e; ++id)
      {
        const auto tile = static_cast<std::int32_t>(id);
        double* p = field.phi(tile);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          p[k] = std::min(gamma, std::max(-gamma, previous.at(field.position(field.node(tile, k)))));
        }
      }
    },
    1);
  exactDistances(field, 0, *plan.Locator, ctx);
  return Status::ok();
}

/// Tiles with a node in the band |phi| < gamma (1.48).
template <int D>
void bandTiles(const TiledField<D>& field, const Context& ctx, std::vector<std::int32_t>& tiles)
{
  std::vector<std::uint8_t> in(static_cast<size_t>(field.tileCount()), 0);
  ctx.parallelFor(0, field.tileCount(),
    [&](Index b, Index e)
    {
      for (Index id = b; id < e; ++id)
      {
        const double* p = field.phi(static_cast<std::int32_t>(id));
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (std::fabs(p[k]) < field.gamma())
          {
            in[static_cast<size_t>(id)] = 1;
            break;
          }
        }
      }
    });
  tiles.clear();
  for (std::int32_t id = 0; id < field.tileCount(); ++id)
  {
    if (in[static_cast<size_t>(id)])
    {
      tiles.push_back(id);
    }
  }
}

/// Gives every band tile all its neighbours (new tiles: the slot's +-gamma, d
/// exact), so that the step and the reinitialisation find every node they
/// read. Returns the number of tiles added.
template <int D>
Status surroundBand(const std::vector<std::int32_t>& band, const PointLocator<D>& locator,
  const ReconstructionOptions& options, int run, const Context& ctx, TiledField<D>& field, Index& added)
{
  added = 0;
  std::vector<Index> missing;
  for (std::int32_t id : band)
  {
    if (!field.surrounded(id))
    {
      forEachSlotAround<D>(field, field.tileOrigin(id),
        [&](Index s)
        {
          if (field.slot(s) < 0)
          {
            missing.push_back(s);
          }
        });
    }
  }
  if (missing.empty())
  {
    return Status::ok();
  }
  std::sort(missing.begin(), missing.end());
  missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  SLTK_RETURN_IF_ERROR(checkTileMemory(field, static_cast<Index>(missing.size()), options, run));
  const std::int32_t first = static_cast<std::int32_t>(field.tileCount());
  for (Index s : missing)
  {
    field.addTile(s);
  }
  exactDistances(field, first, locator, ctx);
  added = static_cast<Index>(missing.size());
  return Status::ok();
}

/// Per-thread scratch of a tile and its neighbourhood.
template <int D>
struct TileScratch
{
  GridField<D> Phi, Dist;
  NodeList Nodes;
  std::vector<double> Values;
};

/// E_p (and E_2) of (4.29)/(4.30) over the band's cells, tile by tile.
template <int D>
Status tiledEnergy(const TiledField<D>& field, const std::vector<std::int32_t>& band, const EnergyOptions& options,
  const Context& ctx, EnergyResult& result)
{
  const Context serial;
  std::vector<EnergyResult> parts(band.size());
  std::vector<Status> failures(band.size());
  ctx.parallelFor(
    0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index j = b; j < e; ++j)
      {
        const std::int32_t id = band[static_cast<size_t>(j)];
        field.scratch(id, 1, 1, s.Phi, &s.Dist);
        s.Nodes.clear();
        const double* p = field.phi(id);
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          if (std::fabs(p[k]) < field.gamma())
          {
            s.Nodes.push_back(scratchNode<D>(k, 1));
          }
        }
        failures[static_cast<size_t>(j)] =
          energyFunctional(s.Phi, s.Dist, s.Nodes, serial, parts[static_cast<size_t>(j)], options);
      }
    },
    16);
  result = EnergyResult{};
  for (size_t j = 0; j < parts.size(); ++j)
  {
    SLTK_RETURN_IF_ERROR(failures[j]);
    result.Integral += parts[j].Integral;
    result.SecondIntegral += parts[j].SecondIntegral;
    result.FrontCells += parts[j].FrontCells;
  }
  energiesFromIntegrals(result, options);
  return Status::ok();
}

/// The largest displacement of a foot of (4.22)/(4.24) from its node, in the
/// same arithmetic as levelSetStep (the scale (4.32), grad d or, through a
/// tunnel, grad phi, and the spread of the tangent points).
template <int D>
double largestFoot(
  const GridField<D>& phi, const GridField<D>& dist, const NodeList& nodes, const LevelSetStepParameters& par)
{
  double largest = 0.0;
  for (Index k : nodes)
  {
    const auto i = phi.nodeIndex(k);
    const double d = dist(i);
    const double scale = cutOff(phi(i), par.Widths) * (par.P == 1.0 ? 1.0 : std::pow(d / par.Energy, par.P - 1.0));
    const auto gd = detail::centredGradient(dist, dist.pointer(i));
    const auto gp = detail::centredGradient(phi, phi.pointer(i));
    double nd = 0.0, np = 0.0;
    for (int a = 0; a < D; ++a)
    {
      nd += gd[a] * gd[a];
      np += gp[a] * gp[a];
    }
    const double speed = std::sqrt(par.DetectTunnels ? std::max(nd, np) : nd);
    const double spread = std::sqrt(2.0 * scale * par.Eta * d * par.TimeStep / par.P) * std::sqrt(D - 1.0);
    largest = std::max(largest, scale * par.TimeStep * speed + spread);
  }
  return largest;
}

/// One step (4.22)/(4.24) on the band, tile by tile: each band tile's new
/// values from the uniform kernel on a copy of the tile and the nodes around
/// it that its feet can reach (measured first on a copy with one node
/// around), stored once all tiles are computed.
template <class Interp, int D>
Status tiledStep(
  TiledField<D>& field, const std::vector<std::int32_t>& band, const LevelSetStepParameters& par, const Context& ctx)
{
  const Context serial;
  const double dx = field.grid().Spacing[0];
  std::vector<double> next(band.size() * static_cast<size_t>(TiledField<D>::Nodes));
  std::vector<Status> failures(band.size());
  std::vector<double> feet(band.size(), 0.0);
  ctx.parallelFor(
    0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index j = b; j < e; ++j)
      {
        const std::int32_t id = band[static_cast<size_t>(j)];
        const double* p = field.phi(id);
        const auto bandNodes = [&](Index halo)
        {
          s.Nodes.clear();
          for (Index k = 0; k < TiledField<D>::Nodes; ++k)
          {
            if (std::fabs(p[k]) < field.gamma())
            {
              s.Nodes.push_back(scratchNode<D>(k, halo));
            }
          }
        };
        field.scratch(id, 1, 1, s.Phi, &s.Dist);
        bandNodes(1);
        const double foot = largestFoot(s.Phi, s.Dist, s.Nodes, par);
        feet[static_cast<size_t>(j)] = foot;
        const Index need = static_cast<Index>(std::ceil(foot / dx)) + StencilReach;
        if (need > MaxHalo)
        {
          continue; // reported below
        }
        const Index halo = std::max<Index>(HaloStep, (need + HaloStep - 1) / HaloStep * HaloStep);
        field.scratch(id, static_cast<int>(halo), Ghost, s.Phi, &s.Dist);
        bandNodes(halo);
        Status status = levelSetStep<Interp, D>(serial, s.Phi, s.Dist, s.Nodes, par, s.Values);
        double* out = next.data() + static_cast<size_t>(j) * TiledField<D>::Nodes;
        for (Index k = 0; k < TiledField<D>::Nodes; ++k)
        {
          out[k] = s.Phi(s.Phi.nodeIndex(scratchNode<D>(k, halo)));
        }
        failures[static_cast<size_t>(j)] = std::move(status);
      }
    },
    4);
  for (size_t j = 0; j < band.size(); ++j)
  {
    if (feet[j] > (MaxHalo - StencilReach) * dx)
    {
      std::ostringstream m;
      m << "a foot of the semi-Lagrangian step moved " << feet[j] / dx << " cells, beyond the "
        << MaxHalo - StencilReach
        << " the tiled reconstruction reads around a tile: use the uniform version or a smaller eta";
      return Status::numericalFailure(m.str());
    }
    SLTK_RETURN_IF_ERROR(failures[j]);
  }
  ctx.parallelFor(0, static_cast<Index>(band.size()),
    [&](Index b, Index e)
    {
      for (Index j = b; j < e; ++j)
      {
        std::copy_n(
          next.data() + j * TiledField<D>::Nodes, TiledField<D>::Nodes, field.phi(band[static_cast<size_t>(j)]));
      }
    });
  return Status::ok();
}

/// Err_P (4.35) and the far-point fraction: |I[phi](Q)| at every point, the
/// points grouped by the tile around them (points in slots without a tile are
/// gamma or more from the front).
template <class Interp, int D>
void cloudErrors(const TiledField<D>& field, const PointCloud<D>& cloud, double far, const Context& ctx,
  double& meanError, double& farFraction)
{
  const GridSpec<D>& g = field.grid();
  std::vector<std::vector<Index>> byTile(static_cast<size_t>(field.tileCount()));
  double sum = 0.0, farCount = 0.0;
  for (Index q = 0; q < cloud.size(); ++q)
  {
    std::array<Index, D> t{};
    bool inside = true;
    for (int a = 0; a < D; ++a)
    {
      const Index i =
        static_cast<Index>(std::floor((cloud.Points[static_cast<size_t>(q)][a] - g.Origin[a]) / g.Spacing[a]));
      t[a] = i >> TileBits;
      inside = inside && i >= 0 && t[a] < field.slotDims()[a];
    }
    const std::int32_t entry = inside ? field.slot(field.slotIndex(t)) : TiledField<D>::Outside;
    if (entry >= 0)
    {
      byTile[static_cast<size_t>(entry)].push_back(q);
    }
    else
    {
      sum += field.gamma();
      farCount += field.gamma() > far ? 1.0 : 0.0;
    }
  }
  std::vector<double> sums(byTile.size(), 0.0), fars(byTile.size(), 0.0);
  ctx.parallelFor(
    0, static_cast<Index>(byTile.size()),
    [&](Index b, Index e)
    {
      TileScratch<D> s;
      for (Index id = b; id < e; ++id)
      {
        const auto& points = byTile[static_cast<size_t>(id)];
        if (points.empty())
        {
          continue;
        }
        field.scratch(static_cast<std::int32_t>(id), TileEdge / 2, Ghost, s.Phi, nullptr);
        Interp interp(s.Phi);
        for (Index q : points)
        {
          const double v = std::fabs(interpolate(interp, s.Phi.spec(), cloud.Points[static_cast<size_t>(q)].data()));
          sums[static_cast<size_t>(id)] += v;
          fars[static_cast<size_t>(id)] += v > far ? 1.0 : 0.0;
        }
      }
    },
    16);
  for (size_t j = 0; j < sums.size(); ++j)
  {
    sum += sums[j];
    farCount += fars[j];
  }
  meanError = sum / static_cast<double>(cloud.size());
  farFraction = farCount / static_cast<double>(cloud.size());
}

/// The iterations of run `run` >= 2 on its tiled field (the uniform version's iterate()).
template <int D, class Interp>
Status iterateTiled(const ReconstructionPlan<D>& plan, int run, const Context& ctx, TiledField<D>& field,
  ReconstructionResult<D>& result, TiledRunRecord& storage, bool& vanished)
{
  vanished = false;
  const ReconstructionOptions& options = plan.Options;
  const auto start = Clock::now();
  const double dx = field.grid().Spacing[0];
  const RunParameters model = options.parameters(run);
  LevelSetStepParameters step;
  step.P = model.P;
  step.Eta = model.Eta;
  step.TimeStep = dx; // (4.36)
  step.Widths = BandWidths::forSpacing(dx, options.BetaFactor, options.GammaFactor);
  step.DetectTunnels = options.DetectTunnels;
  step.TunnelDistance = 2.0 * dx;
  step.TunnelMinDistance = 0.6 * plan.CloudSpacing;
  const double far = std::max(dx * std::ldexp(1.0, run - 1), plan.CloudSpacing);
  double checkedFar = -1.0;
  int nextFarCheck = 0;

  RunRecord<D> record;
  record.Grid = field.grid();
  record.Parameters = model;
  std::vector<std::int32_t> band;
  std::vector<double> energies;
  double bandSizes = 0.0;
  TiledReinitialiser<D> reinit;
  for (int n = 0; n < options.MaxIterations; ++n)
  {
    bandTiles(field, ctx, band);
    Index added = 0;
    SLTK_RETURN_IF_ERROR(surroundBand(band, *plan.Locator, options, run, ctx, field, added));
    storage.AddedTiles += added;
    EnergyOptions energyOptions;
    energyOptions.P = model.P;
    energyOptions.SecondP = model.P != 2.0 ? 2.0 : 0.0;
    EnergyResult ep;
    SLTK_RETURN_IF_ERROR(tiledEnergy(field, band, energyOptions, ctx, ep));
    const double e2 = model.P != 2.0 ? ep.SecondEnergy : ep.Energy;
    if (ep.FrontCells == 0)
    {
      vanished = true;
      return Status::numericalFailure("run " + std::to_string(run) + ": the zero level set vanished (no front cell)");
    }
    energies.push_back(e2);
    if (n >= options.MinIterations && energyStalled(energies, options.EnergyWindow, options.Tolerance) &&
      n >= nextFarCheck)
    {
      if (!options.FollowFarPoints)
      {
        break;
      }
      double error = 0.0, fraction = 0.0;
      cloudErrors<Interp>(field, plan.Cloud, far, ctx, error, fraction);
      if (!stillApproaching(fraction, checkedFar))
      {
        break;
      }
      checkedFar = fraction;
      nextFarCheck = n + options.EnergyWindow;
    }
    step.Energy = ep.Energy;
    reinit.markBand(field, band, options.ReinitDilation, ctx); // the band before the step, dilated (1.53)
    SLTK_RETURN_IF_ERROR((tiledStep<Interp, D>(field, band, step, ctx)));
    SLTK_RETURN_IF_ERROR(reinit.run(field, options.Reinit, ctx));
    IterationRecord it;
    it.Run = run;
    it.Iteration = n + 1;
    it.Energy = e2;
    it.Change = reinit.relativeChange();
    double fraction = 0.0;
    cloudErrors<Interp>(field, plan.Cloud, far, ctx, it.CloudError, fraction);
    it.BandSize = static_cast<Index>(band.size()) * TiledField<D>::Nodes;
    it.Seconds = secondsSince(start);
    result.History.push_back(it);
    record.Iterations = n + 1;
    record.Energy = it.Energy;
    record.CloudError = it.CloudError;
    bandSizes += static_cast<double>(it.BandSize);
    const double progress = (run - 1 + double(n + 1) / options.MaxIterations) / options.Runs;
    if (ctx.interrupter().wasInterrupted(progress))
    {
      result.Runs.push_back(record);
      return Status::aborted();
    }
  }
  record.Seconds = secondsSince(start);
  record.MeanBandSize = record.Iterations ? static_cast<Index>(bandSizes / record.Iterations) : 0;
  double error = 0.0;
  cloudErrors<Interp>(field, plan.Cloud, far, ctx, error, record.FarPoints);
  if (record.Iterations == 0)
  {
    record.CloudError = error;
    record.Energy = energies.empty() ? 0.0 : energies.back();
  }
  std::ostringstream log;
  log << "run " << run << " (tiled): " << record.Iterations << " iterations, E_2 = " << record.Energy
      << ", Err_P = " << record.CloudError << ", " << field.tileCount() << " tiles ("
      << static_cast<double>(field.tileCount()) * TiledField<D>::Nodes / static_cast<double>(field.grid().nodeCount()) *
      100.0
      << "% of the grid), " << record.Seconds << " s";
  ctx.logger().log(LogLevel::Info, log.str());
  result.Runs.push_back(record);
  return Status::ok();
}

template <int D>
void recordStorage(const TiledField<D>& field, int run, Index added, std::vector<TiledRunRecord>& storage)
{
  TiledRunRecord r;
  r.Run = run;
  r.Tiles = field.tileCount();
  r.StoredNodes = field.tileCount() * TiledField<D>::Nodes;
  r.UniformNodes = field.grid().nodeCount();
  r.AddedTiles = added;
  r.Bytes = field.bytes();
  storage.push_back(r);
}

template <int D, class Interp>
Status runTiled(const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result)
{
  ReconstructionResult<D>& records = result.Records;
  SLTK_RETURN_IF_ERROR(reconstructFirstRuns(plan, 1, ctx, records));
  GridField<D> first = std::move(records.SignedDistance);
  records.Distance = GridField<D>{};
  first.fillGhosts();
  const double firstGamma = plan.Options.GammaFactor * first.spec().Spacing[0];
  PreviousLevelSet<D> previous;
  previous.Dense = &first;
  TiledField<D> last;
  if (plan.Options.Runs == 1)
  {
    // One run: its uniform result, stored in tiles.
    SLTK_RETURN_IF_ERROR(transferToTiles(previous, firstGamma, first.spec(), plan, 1, ctx, result.Field));
    recordStorage(result.Field, 1, 0, result.Storage);
    return Status::ok();
  }
  double previousGamma = firstGamma;
  for (int run = 2; run <= plan.Options.Runs; ++run)
  {
    const GridSpec<D>& grid = plan.Grids.Runs[static_cast<size_t>(run - 1)];
    ctx.interrupter().start("run " + std::to_string(run) + "/" + std::to_string(plan.Options.Runs) + " (tiled)");
    const auto setup = Clock::now();
    TiledField<D> field;
    SLTK_RETURN_IF_ERROR(transferToTiles(previous, previousGamma, grid, plan, run, ctx, field));
    TiledReinitialiser<D> reinit;
    std::vector<std::int32_t> band;
    bandTiles(field, ctx, band);
    reinit.markBand(field, band, plan.Options.ReinitDilation, ctx);
    SLTK_RETURN_IF_ERROR(reinit.run(field, plan.Options.Reinit, ctx));
    std::ostringstream log;
    log << "run " << run << " (tiled): " << field.tileCount() << " tiles of " << field.slotCount() << " ("
        << field.bytes() / 1048576.0 << " MB), set up in " << secondsSince(setup) << " s";
    ctx.logger().log(LogLevel::Info, log.str());
    if (run == 2)
    {
      first = GridField<D>{}; // run 1's grid is no longer needed
    }
    else
    {
      last = TiledField<D>{};
    }
    TiledRunRecord storage;
    bool vanished = false;
    const Status status = iterateTiled<D, Interp>(plan, run, ctx, field, records, storage, vanished);
    ctx.interrupter().end();
    recordStorage(field, run, storage.AddedTiles, result.Storage);
    SLTK_RETURN_IF_ERROR(status);
    last = std::move(field);
    previous.Dense = nullptr;
    previous.Tiled = &last;
    previousGamma = last.gamma();
  }
  result.Field = std::move(last);
  return Status::ok();
}
} // namespace

template <int D>
Status reconstructTiled(const ReconstructionPlan<D>& plan, const Context& ctx, TiledReconstructionResult<D>& result)
{
  result = TiledReconstructionResult<D>{};
  result.Box = plan.Box;
  const Status status = withInterpolator<D>(
    plan.Options.Interpolator, [&](auto tag) { return runTiled<D, typename decltype(tag)::type>(plan, ctx, result); });
  recordsToUser(plan.Box, result.Records);
  result.Records.CloudSpacing *= plan.Box.Scale;
  return status;
}

template Status reconstructTiled(const ReconstructionPlan<2>&, const Context&, TiledReconstructionResult<2>&);
template Status reconstructTiled(const ReconstructionPlan<3>&, const Context&, TiledReconstructionResult<3>&);

} // namespace sltk
