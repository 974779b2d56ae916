// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file SlabRuns.h
/// The runs of Algorithm 1 on uniform grids (RunLoop.h): each run's grid cut
/// into slabs over the ranks (RunSlab.h; the whole grid on one rank), the
/// distance to the cloud (4.4.2) and the initial data (4.4.4) of run 1, the
/// previous run's phi and d interpolated on a later run's grid, and the
/// iterations on the slab band (SlabBand.h).

#include "sltk/interp/Q1.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/CloudInitialDataSlabs.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/FarPointSeeds.h"
#include "sltk/recon/InsideComponents.h"
#include "sltk/recon/LocalOffset.h"
#include "sltk/recon/SlabPolicy.h"

#include "RunPoints.h"
#include "RunSlab.h"
#include "SlabBand.h"
#include "sltk/recon/RunIterations.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace sltk
{

constexpr int PhiGhost = 2; // WENO3 / CWENO stencils (Q1 needs 1)

// The owner of a far foot must hold its stencil: Interp::GhostWidth + 2 rows (footInWindow()).
static_assert(SlabGhostRows >= PhiGhost + 2, "the owner of a far foot holds its stencil");

/// The previous run's phi (ghosts filled, on `fromSlab`'s window) interpolated
/// at the owned nodes of `slab`'s window (Q1: monotone); the ghost rows then
/// come from their owners. Each rank's owned rows lie inside its previous
/// window with a row to spare (RunSlab::plan cuts a later run's grid near
/// where the previous run's slabs meet, within laterCutRange(), SlabPolicy.h):
/// checked.
template <int D>
Status transfer(
  const GridField<D>& from, const RunSlab<D>& fromSlab, const RunSlab<D>& slab, const Context& ctx, GridField<D>& to)
{
  const GridSpec<D> grid = slab.window();
  to.resize(grid, PhiGhost);
  const Index b = slab.ownedBegin(), e = slab.ownedEnd();
  // The previous window's rows, but for its ghost rows' outermost (one rank: every row).
  const GridSpec<D>& f = from.spec();
  const SlabPlan& fs = fromSlab.slab();
  const double lowest = fs.First > 0 ? f.coordinate(D - 1, 1) : -HUGE_VAL;
  const double highest = fs.Stop < fromSlab.rows() ? f.coordinate(D - 1, f.Dims[D - 1] - 2) : HUGE_VAL;
  const double firstOwned = grid.coordinate(D - 1, slab.slab().Begin - slab.slab().First);
  const double lastOwned = grid.coordinate(D - 1, slab.slab().End - 1 - slab.slab().First);
  const Status covered = firstOwned >= lowest && lastOwned <= highest
    ? Status::ok()
    : Status::invalidArgument("the previous run's slab does not cover this run's owned rows (rank " +
        std::to_string(slab.comm().rank()) + "): run on fewer ranks");
  SLTK_RETURN_IF_ERROR(slab.agree(covered));
  const Index nx = grid.Dims[0]; // the owned rows are whole x lines
  q1Resample(from, b / nx, e / nx, ctx, to);
  slab.exchange(to);
  return Status::ok();
}

/// Run 1's phi0 from the distance (4.4.4), with the local offset when the plan
/// has one (rho from this rank's points).
template <int D>
Status cloudInitialDataOn(const ReconstructionPlan<D>& plan, const RunPoints<D>& points, double outsideFactor,
  const GridField<D>& dist, const RunSlab<D>& slab, const Context& ctx, GridField<D>& phi)
{
  InitialDataOptions io;
  io.Ghost = PhiGhost;
  const double threshold = outsideFactor * plan.CloudSpacing;
  const auto phi0 = [&](const GridField<D>& u)
  { return cloudInitialDataSlabs(u, threshold, slab.slab(), slab.rows(), slab.comm(), ctx, phi, io); };
  if (plan.Sparsity.empty())
  {
    return phi0(dist);
  }
  // The local offset K_P h_P rho(x) (LocalOffset.h): the marking and sweeping on u = d / rho.
  const double sparsest = *std::max_element(plan.Sparsity.begin(), plan.Sparsity.end());
  const double reach = sparsest * outsideFactor * plan.CloudSpacing;
  GridField<D> scaled;
  SLTK_RETURN_IF_ERROR(locallyScaledDistanceSlabs(
    dist, points.locator(), points.sparsity(), reach, slab.slab(), slab.comm(), ctx, scaled));
  return phi0(scaled);
}

/// Initial data of a run: run 1 from the cloud (4.4.4) or an ellipsoid, later
/// runs from the previous result; cut (1.49) and made a distance near the front.
template <int D>
Status initialData(const ReconstructionPlan<D>& plan, const RunPoints<D>& points, double outsideFactor,
  const GridField<D>& dist, const GridField<D>* previous, const RunSlab<D>* previousSlab, const FarPointSeeds<D>& seeds,
  const RunSlab<D>& slab, const Context& ctx, GridField<D>& phi)
{
  const ReconstructionOptions& options = plan.Options;
  const GridSpec<D> grid = slab.window();
  const double gamma = options.GammaFactor * grid.Spacing[0];
  if (previous)
  {
    SLTK_RETURN_IF_ERROR(transfer(*previous, *previousSlab, slab, ctx, phi));
    if (!seeds.empty()) // what the previous run lost (FarPointSeeds.h)
    {
      const SlabPlan& s = slab.slab();
      addSeedBalls(seeds, gamma, s.Begin - s.First, s.End - s.First, ctx, phi);
      slab.exchange(phi);
    }
  }
  else if (plan.InitialEllipsoid)
  {
    SLTK_RETURN_IF_ERROR(slab.agree(ellipsoidLevelSet(*plan.InitialEllipsoid, grid, ctx, phi, PhiGhost)));
  }
  else
  {
    SLTK_RETURN_IF_ERROR(cloudInitialDataOn(plan, points, outsideFactor, dist, slab, ctx, phi));
  }
  cutLevelSet(phi, gamma, ctx);
  if (previous)
  {
    NodeList band, wide;
    collectBand(phi, gamma, ctx, band); // the window's: ghost rows' nodes dilate into the owned rows
    dilateBand(grid, band, options.ReinitDilation, ctx, wide);
    slab.keepOwned(wide);
    SLTK_RETURN_IF_ERROR(reinitialiseOn(phi, wide, slab, options.Reinit, ctx));
    cutLevelSet(phi, wide, gamma, ctx);
    slab.exchange(phi);
  }
  phi.fillGhosts();
  return Status::ok();
}

/// The uniform storage of the runs (RunLoop.h's `Runs`): phi and d of the
/// current run and of the previous one on this rank's slabs.
template <int D, class Interp>
class SlabRuns
{
public:
  SlabRuns(const ReconstructionPlan<D>& plan, const ReconstructionOptions& options,
    const std::vector<GridSpec<D>>& grids, const Context& ctx, const Communicator& comm)
    : Plan(plan)
    , Options(options)
    , Grids(grids)
    , Ctx(ctx)
    , Exact(*plan.Locator)
    , Slab(comm)
    , PreviousSlab(comm)
  {
  }

  /// Run `run`'s slab, d and initial data: run 1 from the cloud with K_P =
  /// `outsideFactor`, later runs from the previous run.
  Status setUp(int run, double outsideFactor)
  {
    const GridSpec<D>& grid = this->Grids[static_cast<size_t>(run - 1)];
    const auto setup = std::chrono::steady_clock::now();
    SLTK_RETURN_IF_ERROR(this->Slab.plan(grid, this->Plan.Cloud, run > 1 ? &this->PreviousSlab : nullptr));
    const Communicator& comm = this->Slab.comm();
    this->Points.select(
      this->Plan, this->Slab.window(), PhiGhost, RunPoints<D>::reachFor(this->Plan, grid, run, outsideFactor), comm);
    this->Exact.bind(this->Points.locator(), this->Points.reach(), comm);
    if (run == 1)
    {
      DistanceOptions dopt;
      dopt.Ghost = PhiGhost;
      SLTK_RETURN_IF_ERROR(distanceToCloudSlabs(
        this->Points.locator(), grid, this->Slab.slab(), comm, this->Ctx, this->Dist, dopt)); // (4.4.2)
    }
    else
    {
      // Later runs: d interpolated from the previous run; exact values follow the band.
      SLTK_RETURN_IF_ERROR(transfer(this->PreviousDist, this->PreviousSlab, this->Slab, this->Ctx, this->Dist));
      this->Dist.fillGhosts();
    }
    const double distanceSeconds = detail::secondsSince(setup);
    SLTK_RETURN_IF_ERROR(
      initialData(this->Plan, this->Points, outsideFactor, this->Dist, run > 1 ? &this->Previous : nullptr,
        run > 1 ? &this->PreviousSlab : nullptr, this->Seeds, this->Slab, this->Ctx, this->Phi));
    std::ostringstream log;
    log << "run " << run << ": grid " << grid.nodeCount() << " nodes, distance " << distanceSeconds
        << " s, initial data " << detail::secondsSince(setup) - distanceSeconds << " s";
    if (run > 1 && this->Options.SeedFarPoints)
    {
      log << ", " << this->Seeds.Centres.size() << " point(s) run " << run - 1 << " left outside seeded back";
    }
    if (this->Slab.distributed())
    {
      const SlabPlan& s = this->Slab.slab();
      log << "; rank " << this->Slab.comm().rank() << " of " << this->Slab.comm().size() << " owns rows " << s.Begin
          << ".." << s.End - 1 << " of " << this->Slab.rows() << " (" << s.Ghost << " ghost rows), reads "
          << this->Points.held() << " of the " << this->Points.total() << " points";
    }
    this->Ctx.logger().log(LogLevel::Info, log.str());
    return Status::ok();
  }

  Status iterate(int run, ReconstructionResult<D>& result, bool& vanished)
  {
    SlabBand<D, Interp> band(this->Points, this->Options, this->Ctx, this->Exact, this->Slab, this->Phi, this->Dist);
    const Status status = iterateRun<D>(band, this->Options, run, this->Plan.CloudSpacing, this->Ctx, result, vanished);
    const bool ran = status.isOk() && !vanished;
    this->Seeds = seedsAfterRun<D>(band, this->Plan.CloudSpacing, this->Options, run, ran, this->Slab.comm());
    result.MissedPlaces = missedPlacesAfterRun(
      band, *this->Plan.Locator, this->Plan.CloudSpacing, this->Options, run, ran, result.Runs, this->Slab.comm());
    // d was made exact where each rank's band reached: the ghost rows take the
    // owners' values (the next run interpolates them; the blocks share a row).
    this->Slab.exchange(this->Dist);
    return status;
  }

  /// The ranks the runs are split over.
  const Communicator& comm() const { return this->Slab.comm(); }

  /// The balls the next run adds: the points this run left outside (empty after the last run).
  const FarPointSeeds<D>& seeds() const { return this->Seeds; }

  /// This run's result becomes the previous run's (the next run's cut follows its band).
  void advance(int run)
  {
    this->Slab.recordBand(this->Phi, this->Options.GammaFactor * this->Grids[static_cast<size_t>(run - 1)].Spacing[0]);
    this->Previous = std::move(this->Phi);
    this->PreviousDist = std::move(this->Dist);
    this->PreviousSlab = this->Slab;
  }

  /// The result is this run's (also when it failed: what it reached).
  Status keepCurrent(int, ReconstructionResult<D>& result)
  {
    keep(std::move(this->Phi), std::move(this->Dist), this->Slab, result);
    return Status::ok();
  }
  void keepFailed(int run, ReconstructionResult<D>& result) { this->keepCurrent(run, result); }

  /// The pieces of the kept result (InsideComponents.h).
  std::int64_t pieces(const ReconstructionResult<D>& result) const
  {
    const Communicator& comm = this->Slab.comm();
    return insideComponents<D>(SlabNodes<D>(result.SignedDistance, result.WholeGrid, result.Slab, comm.rank()), comm);
  }

  /// The result is the previous run's, on its grid.
  Status keepPrevious(int, ReconstructionResult<D>& result)
  {
    keep(std::move(this->Previous), std::move(this->PreviousDist), this->PreviousSlab, result);
    return Status::ok();
  }

private:
  static void keep(GridField<D>&& phi, GridField<D>&& dist, const RunSlab<D>& of, ReconstructionResult<D>& result)
  {
    result.SignedDistance = std::move(phi);
    result.Distance = std::move(dist);
    result.WholeGrid = of.whole();
    result.Slab = of.slab();
  }

  const ReconstructionPlan<D>& Plan;
  const ReconstructionOptions& Options;
  const std::vector<GridSpec<D>>& Grids;
  const Context& Ctx;
  ExactDistanceCache<D> Exact; // one for all runs
  RunPoints<D> Points;         // this run's points on this rank (RunPoints.h)
  GridField<D> Phi, Previous, Dist, PreviousDist;
  RunSlab<D> Slab, PreviousSlab;
  FarPointSeeds<D> Seeds; // what the last run left outside, for the next (FarPointSeeds.h)
};

} // namespace sltk
