// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/Reconstruction.h"

#include "sltk/levelset/NarrowBand.h"
#include "sltk/levelset/Reinitialise.h"
#include "sltk/levelset/ReinitialiseSlabs.h"
#include "sltk/recon/CloudError.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/recon/CloudInitialDataSlabs.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/ExactDistanceCache.h"
#include "sltk/recon/FarFeetExchange.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/LocalOffset.h"
#include "sltk/recon/ReconstructionInterpolator.h"
#include "sltk/recon/SlabPolicy.h"
#include "sltk/recon/StoppingRule.h"
#include "sltk/recon/StrayPoints.h"

#include "RunSlab.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace sltk
{

namespace
{
constexpr int PhiGhost = 2; // WENO3 / CWENO stencils (Q1 needs 1)
double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The owner of a far foot must hold its stencil: Interp::GhostWidth + 2 rows (footInWindow()).
static_assert(SlabGhostRows >= PhiGhost + 2, "the owner of a far foot holds its stencil");

/// Err_P (4.35): mean |I[phi](Q)| over the cloud (phi's ghosts filled), each
/// rank summing the points of its owned cells.
template <int D, class Interp>
double cloudError(const GridField<D>& phi, const PointCloud<D>& cloud, const RunSlab<D>& slab, const Context& ctx)
{
  const SlabPlan& s = slab.slab();
  return slab.sum(cloudErrorSum<D, Interp>(phi, cloud, ctx, s.Begin, s.End, slab.rows())) /
    static_cast<double>(cloud.size());
}

/// The fraction of the cloud's points farther than `far` from the zero level
/// set, |I[phi](Q)| > far (phi a distance near the front): parts of the object
/// the surface lost (thin features collapsed on a coarse grid).
template <int D, class Interp>
double farPointFraction(
  const GridField<D>& phi, const PointCloud<D>& cloud, double far, const RunSlab<D>& slab, const Context& ctx)
{
  const SlabPlan& s = slab.slab();
  const double count = sumOverPoints<D, Interp>(
    phi, cloud, ctx, s.Begin, s.End, slab.rows(), [far](double v) { return std::fabs(v) > far ? 1.0 : 0.0; });
  return slab.sum(count) / static_cast<double>(cloud.size());
}

/// phi at `nodes`, in order: phi^n where an iteration may change it (for eps_1).
template <int D>
void gatherValues(const GridField<D>& phi, const NodeList& nodes, std::vector<double>& values)
{
  values.resize(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k)
  {
    values[k] = phi(phi.nodeIndex(nodes[k]));
  }
}

/// The sums of eps_1^n (4.34) restricted to `nodes`, added to sums[0] (sum
/// |phi^{n+1} - phi^n|) and sums[1] (sum |phi^n|), with phi^{n+1} the iterate
/// after reinitialisation and cut and `before` = phi^n at the same nodes
/// (gatherValues). Nodes outside the set did not change.
template <int D>
void addUpdateSums(const GridField<D>& phi, const NodeList& nodes, const std::vector<double>& before, double* sums)
{
  for (size_t k = 0; k < nodes.size(); ++k)
  {
    sums[0] += std::fabs(phi(phi.nodeIndex(nodes[k])) - before[k]);
    sums[1] += std::fabs(before[k]);
  }
}

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
  if (slab.distributed())
  {
    const GridSpec<D>& f = from.spec();
    const SlabPlan& fs = fromSlab.slab();
    const double lowest = fs.First > 0 ? f.coordinate(D - 1, 1) : -HUGE_VAL;
    const double highest = fs.Stop < fromSlab.rows() ? f.coordinate(D - 1, f.Dims[D - 1] - 2) : HUGE_VAL;
    const double first = grid.coordinate(D - 1, slab.slab().Begin - slab.slab().First);
    const double last = grid.coordinate(D - 1, slab.slab().End - 1 - slab.slab().First);
    const Status covered = first >= lowest && last <= highest
      ? Status::ok()
      : Status::invalidArgument("the previous run's slab does not cover this run's owned rows (rank " +
          std::to_string(slab.comm().rank()) + "): run on fewer ranks");
    SLTK_RETURN_IF_ERROR(slab.agree(covered));
  }
  ctx.parallelFor(b, e,
    [&](Index first, Index stop)
    {
      Q1Interpolator<D> interp(from);
      for (Index k = first; k < stop; ++k)
      {
        const auto i = to.nodeIndex(k);
        double x[D];
        for (int a = 0; a < D; ++a)
        {
          x[a] = grid.coordinate(a, i[a]);
        }
        to(i) = interpolate(interp, from.spec(), x);
      }
    });
  slab.exchange(to);
  return Status::ok();
}

/// The reinitialisation (1.38)-(1.45) of the owned nodes `nodes`, on slabs when distributed.
template <int D>
Status reinitialiseOn(
  GridField<D>& phi, const NodeList& nodes, const RunSlab<D>& slab, const ReinitOptions& options, const Context& ctx)
{
  return slab.distributed() ? reinitialiseSlabs<D>(phi, nodes, slab.slab(), slab.comm(), options, ctx)
                            : reinitialise<D>(phi, nodes, options, ctx);
}

/// The iterations of one run on its grid (Algorithm 1, step 4).
template <int D, class Interp>
Status iterate(const PointCloud<D>& cloud, const ReconstructionOptions& options, int run, const Context& ctx,
  ExactDistanceCache<D>& exact, RunSlab<D>& slab, GridField<D>& phi, GridField<D>& dist,
  ReconstructionResult<D>& result, bool& vanished)
{
  vanished = false;
  const auto start = std::chrono::steady_clock::now();
  const double dx = phi.spec().Spacing[0];
  const RunParameters model = options.parameters(run);
  LevelSetStepParameters step;
  step.P = model.P;
  step.Eta = model.Eta;
  step.TimeStep = dx; // (4.36): dt = dx
  step.Widths = BandWidths::forSpacing(dx, options.BetaFactor, options.GammaFactor);
  // h_P in the unit box: dx = C_dx h_P / 2^(run-1) (4.36).
  const double cloudSpacing =
    options.CellSizeFactor > 0.0 ? dx * std::ldexp(1.0, run - 1) / options.CellSizeFactor : dx;
  step.DetectTunnels = options.DetectTunnels;
  step.TunnelDistance = 2.0 * dx; // 4.5.6
  step.TunnelMinDistance = 0.6 * cloudSpacing;
  const double gamma = step.Widths.Gamma;
  // One cell of run 1, C_dx h_P (4.36), and at least h_P: farther points are "far".
  const double far = std::max(dx * std::ldexp(1.0, run - 1), cloudSpacing);
  double checkedFar = -1.0; // FollowFarPoints: the fraction at the last check, and when to check again
  int nextFarCheck = 0;

  RunRecord<D> record;
  record.Grid = slab.whole();
  record.Parameters = model;
  NodeList band, reinitBand, ghostBand; // band: the owned rows' B^n; ghostBand: the adjacent ghost rows'
  std::vector<std::uint8_t> dilationScratch;
  std::vector<double> stepScratch, previousValues;
  std::vector<double> energies;
  FarFeet<D> farFeet;
  slab.frameFarFeet(farFeet);
  double bandSizes = 0.0;
  double phase[4] = { 0.0, 0.0, 0.0, 0.0 }; // energy, step, reinitialisation, metrics (seconds)
  collectBand(phi, gamma, ctx, band);       // (1.50)
  slab.keepOwned(band);
  exact.reset(dist);
  for (int n = 0; n < options.MaxIterations; ++n)
  {
    exact.ensure(band, ctx, dist);
    // On slabs d is made exact on the stencils of the ghost rows' band nodes
    // too: their stencils (one row) and dilation (1.53) reach the owned rows,
    // as the one-rank band does.
    slab.ghostBand(phi, gamma, std::max<Index>(1, options.ReinitDilation), ghostBand);
    exact.ensure(ghostBand, ctx, dist);
    // (4.29)/(4.30) on the cells of the band: E_p for the scale factor, E_2 for (4.33).
    auto clock = std::chrono::steady_clock::now();
    EnergyResult ep;
    EnergyOptions energyOptions;
    energyOptions.P = model.P;
    energyOptions.SecondP = model.P != 2.0 ? 2.0 : 0.0; // E_2 in the same pass
    SLTK_RETURN_IF_ERROR(slab.agree(energyFunctional(phi, dist, band, ctx, ep, energyOptions)));
    if (slab.distributed())
    {
      reduceEnergy(ep, energyOptions, slab.comm());
    }
    EnergyResult e2 = ep;
    if (model.P != 2.0)
    {
      e2.Integral = ep.SecondIntegral;
      e2.Energy = ep.SecondEnergy;
    }
    if (ep.FrontCells == 0)
    {
      vanished = true;
      return Status::numericalFailure("run " + std::to_string(run) + ": the zero level set vanished (no front cell)");
    }
    energies.push_back(e2.Energy);
    if (n >= options.MinIterations && energyStalled(energies, options.EnergyWindow, options.Tolerance) &&
      n >= nextFarCheck)
    {
      if (!options.FollowFarPoints)
      {
        break;
      }
      // Beyond the thesis: stalled by (4.33), but still approaching far points?
      const double fraction = farPointFraction<D, Interp>(phi, cloud, far, slab, ctx);
      if (!stillApproaching(fraction, checkedFar))
      {
        break;
      }
      checkedFar = fraction;
      nextFarCheck = n + options.EnergyWindow;
    }
    step.Energy = ep.Energy;
    phase[0] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();
    // The step writes the band, the reinitialisation its dilation (1.53): phi^n there for eps_1 (4.34).
    // On slabs the ghost rows' band nodes dilate into the owned rows too.
    dilateBand(phi.spec(), band, options.ReinitDilation, dilationScratch, reinitBand, &ghostBand);
    slab.keepOwned(reinitBand);
    gatherValues(phi, reinitBand, previousValues);
    // (4.22)/(4.24); on slabs the feet beyond the window are interpolated by their owners.
    SLTK_RETURN_IF_ERROR(slab.agree(
      levelSetStepValues<Interp, D>(ctx, phi, dist, band, step, stepScratch, slab.distributed() ? &farFeet : nullptr)));
    if (slab.distributed())
    {
      double feet = 0.0;
      SLTK_RETURN_IF_ERROR(resolveFarFeet<Interp>(phi, farFeet, slab.whole(), slab.boundaries(), slab.comm(), feet));
      SLTK_RETURN_IF_ERROR(slab.agree(finishFarNodes(farFeet, stepScratch)));
      record.FarFeet += static_cast<Index>(feet);
    }
    storeLevelSetStep(ctx, phi, band, stepScratch);
    slab.exchange(phi, ReinitEntryRows); // what the reinitialisation reads; every ghost row after the cut
    phase[1] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();
    SLTK_RETURN_IF_ERROR(reinitialiseOn(phi, reinitBand, slab, options.Reinit, ctx));
    cutLevelSet(phi, reinitBand, gamma, ctx); // (1.49)
    slab.exchange(phi);
    phi.fillGhosts();
    filterBand(phi, reinitBand, gamma, ctx, band); // (1.54)
    phase[2] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();

    IterationRecord it;
    it.Run = run;
    it.Iteration = n + 1;
    it.Energy = e2.Energy;
    const double fraction = (run - 1 + double(n + 1) / options.MaxIterations) / options.Runs;
    const bool interrupted = ctx.interrupter().wasInterrupted(fraction);
    // This rank's sums of eps_1 (4.34) between successive iterates and of Err_P (4.35) over the
    // points of its owned cells, its band size and whether it was interrupted: one all-reduce.
    double sums[5] = { 0.0, 0.0,
      cloudErrorSum<D, Interp>(phi, cloud, ctx, slab.slab().Begin, slab.slab().End, slab.rows()),
      static_cast<double>(band.size()), interrupted ? 1.0 : 0.0 };
    addUpdateSums(phi, reinitBand, previousValues, sums);
    if (slab.distributed())
    {
      slab.comm().allReduce(sums, 5, ReduceOp::Sum);
    }
    it.Change = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
    it.CloudError = sums[2] / static_cast<double>(cloud.size());
    it.BandSize = static_cast<Index>(sums[3]);
    it.Seconds = secondsSince(start);
    result.History.push_back(it);
    record.Iterations = n + 1;
    record.Energy = it.Energy;
    record.CloudError = it.CloudError;
    bandSizes += static_cast<double>(it.BandSize);
    phase[3] += secondsSince(clock);

    if (sums[4] > 0.0) // every rank stops
    {
      result.Runs.push_back(record);
      return Status::aborted();
    }
  }
  record.Seconds = secondsSince(start);
  record.GhostRows = slab.slab().Ghost;
  record.MeanBandSize = record.Iterations ? static_cast<Index>(bandSizes / record.Iterations) : 0;
  if (record.Iterations == 0)
  {
    record.Energy = energies.empty() ? 0.0 : energies.back();
    phi.fillGhosts();
    record.CloudError = cloudError<D, Interp>(phi, cloud, slab, ctx);
  }
  const double spacing = cloudSpacing;
  record.FarPoints = farPointFraction<D, Interp>(phi, cloud, far, slab, ctx);
  if (run == options.Runs && record.FarPoints > FarPointWarning)
  {
    std::ostringstream warning;
    warning << "run " << run << ": " << 100.0 * record.FarPoints
            << "% of the points lie more than one cell of run 1 from the surface: features thinner than that cell "
            << "were lost; try "
            << "half the C_dx with one run fewer (the same finest grid)";
    ctx.logger().log(LogLevel::Warning, warning.str());
  }
  if (record.CloudError > 2.0 * spacing)
  {
    std::ostringstream warning;
    warning << "run " << run << " ended with Err_P = " << record.CloudError / spacing
            << " h_P: the surface did not reach the cloud; try a larger K_P (holes), a larger eta or a smaller C_dx";
    ctx.logger().log(LogLevel::Warning, warning.str());
  }
  std::ostringstream log;
  log << "run " << run << ": " << record.Iterations << " iterations, E_2 = " << record.Energy
      << ", Err_P = " << record.CloudError << ", " << record.Seconds << " s (energy " << phase[0] << " s, SL step "
      << phase[1] << " s, reinitialisation " << phase[2] << " s, metrics " << phase[3] << " s)";
  ctx.logger().log(LogLevel::Info, log.str());
  result.Runs.push_back(record);
  return Status::ok();
}

/// Run 1's phi0 from the distance (4.4.4), with the local offset when the plan has one.
template <int D>
Status cloudInitialDataOn(const ReconstructionPlan<D>& plan, double outsideFactor, const GridField<D>& dist,
  const RunSlab<D>& slab, const Context& ctx, GridField<D>& phi)
{
  InitialDataOptions io;
  io.Ghost = PhiGhost;
  const double threshold = outsideFactor * plan.CloudSpacing;
  const auto phi0 = [&](const GridField<D>& u)
  {
    return slab.distributed() ? cloudInitialDataSlabs(u, threshold, slab.slab(), slab.rows(), slab.comm(), ctx, phi, io)
                              : cloudInitialData(u, threshold, ctx, phi, io);
  };
  if (plan.Sparsity.empty())
  {
    return phi0(dist);
  }
  // The local offset K_P h_P rho(x) (LocalOffset.h): the marking and sweeping on u = d / rho.
  const double sparsest = *std::max_element(plan.Sparsity.begin(), plan.Sparsity.end());
  const double reach = sparsest * outsideFactor * plan.CloudSpacing;
  GridField<D> scaled;
  SLTK_RETURN_IF_ERROR(slab.distributed()
      ? locallyScaledDistanceSlabs(dist, *plan.Locator, plan.Sparsity, reach, slab.slab(), slab.comm(), ctx, scaled)
      : locallyScaledDistance(dist, *plan.Locator, plan.Sparsity, reach, ctx, scaled));
  return phi0(scaled);
}

/// Initial data of a run: run 1 from the cloud (4.4.4) or an ellipsoid, later
/// runs from the previous result; cut (1.49) and made a distance near the front.
template <int D>
Status initialData(const ReconstructionPlan<D>& plan, double outsideFactor, const GridField<D>& dist,
  const GridField<D>* previous, const RunSlab<D>* previousSlab, const RunSlab<D>& slab, const Context& ctx,
  GridField<D>& phi)
{
  const ReconstructionOptions& options = plan.Options;
  const GridSpec<D> grid = slab.window();
  const double gamma = options.GammaFactor * grid.Spacing[0];
  if (previous)
  {
    SLTK_RETURN_IF_ERROR(transfer(*previous, *previousSlab, slab, ctx, phi));
  }
  else if (plan.InitialEllipsoid)
  {
    SLTK_RETURN_IF_ERROR(slab.agree(ellipsoidLevelSet(*plan.InitialEllipsoid, grid, ctx, phi, PhiGhost)));
  }
  else
  {
    SLTK_RETURN_IF_ERROR(cloudInitialDataOn(plan, outsideFactor, dist, slab, ctx, phi));
  }
  cutLevelSet(phi, gamma, ctx);
  if (previous)
  {
    NodeList band, wide;
    std::vector<std::uint8_t> scratch;
    collectBand(phi, gamma, ctx, band); // the window's: ghost rows' nodes dilate into the owned rows
    dilateBand(grid, band, options.ReinitDilation, scratch, wide);
    slab.keepOwned(wide);
    SLTK_RETURN_IF_ERROR(reinitialiseOn(phi, wide, slab, options.Reinit, ctx));
    cutLevelSet(phi, wide, gamma, ctx);
    slab.exchange(phi);
  }
  phi.fillGhosts();
  return Status::ok();
}

/// Drops the history of `run`: a run that lost its zero level set and is redone or replaced.
template <int D>
void forgetRun(int run, ReconstructionResult<D>& result)
{
  auto& h = result.History;
  h.erase(std::remove_if(h.begin(), h.end(), [run](const IterationRecord& it) { return it.Run == run; }), h.end());
}

template <int D>
void recover(const std::string& what, const Context& ctx, ReconstructionResult<D>& result)
{
  ctx.logger().log(LogLevel::Warning, what);
  result.Recoveries.push_back(what);
}

/// Runs 1..lastRun of Algorithm 1 on `grids` (options.Runs of them) with `options`
/// (the plan's, or a finer start: reconstruct()).
template <int D, class Interp>
Status runAll(const ReconstructionPlan<D>& plan, const ReconstructionOptions& options,
  const std::vector<GridSpec<D>>& grids, const Context& ctx, const Communicator& comm, ReconstructionResult<D>& result,
  int lastRun)
{
  const PointCloud<D>& cloud = plan.Cloud;
  ExactDistanceCache<D> exact(cloud, *plan.Locator);
  GridField<D> phi, previous, dist, previousDist;
  RunSlab<D> slab(comm), previousSlab(comm);
  const auto keep = [&](GridField<D>&& signedDistance, GridField<D>&& distance, const RunSlab<D>& of)
  {
    result.SignedDistance = std::move(signedDistance);
    result.Distance = std::move(distance);
    result.WholeGrid = of.whole();
    result.Slab = of.slab();
  };
  double outsideFactor = options.OutsideThresholdFactor;
  // An automatic K_P may be raised when run 1 loses its zero level set (AutomaticParameters.h).
  const double outsideRoom = plan.Enclosure ? outsideFactorWithRestart(outsideFactor) : outsideFactor;
  for (int run = 1; run <= lastRun; ++run)
  {
    const GridSpec<D>& grid = grids[static_cast<size_t>(run - 1)];
    ctx.interrupter().start("run " + std::to_string(run) + "/" + std::to_string(options.Runs));
    const auto setup = std::chrono::steady_clock::now();
    SLTK_RETURN_IF_ERROR(slab.plan(grid, cloud, run > 1 ? &previousSlab : nullptr));
    if (run == 1)
    {
      DistanceOptions dopt;
      dopt.Ghost = PhiGhost;
      SLTK_RETURN_IF_ERROR(slab.distributed()
          ? distanceToCloudSlabs(*plan.Locator, grid, slab.slab(), comm, ctx, dist, dopt)
          : distanceToCloud(*plan.Locator, grid, ctx, dist, dopt)); // (4.4.2)
    }
    else
    {
      // Later runs: d interpolated from the previous run; exact values follow the band.
      SLTK_RETURN_IF_ERROR(transfer(previousDist, previousSlab, slab, ctx, dist));
      dist.fillGhosts();
    }
    const double distanceSeconds = secondsSince(setup);
    SLTK_RETURN_IF_ERROR(initialData(
      plan, outsideFactor, dist, run > 1 ? &previous : nullptr, run > 1 ? &previousSlab : nullptr, slab, ctx, phi));
    std::ostringstream log;
    log << "run " << run << ": grid " << grid.nodeCount() << " nodes, distance " << distanceSeconds
        << " s, initial data " << secondsSince(setup) - distanceSeconds << " s";
    if (slab.distributed())
    {
      log << "; rank " << comm.rank() << " of " << comm.size() << " owns rows " << slab.slab().Begin << ".."
          << slab.slab().End - 1 << " of " << slab.rows() << " (" << slab.slab().Ghost << " ghost rows)";
    }
    ctx.logger().log(LogLevel::Info, log.str());
    bool vanished = false;
    const Status status = iterate<D, Interp>(cloud, options, run, ctx, exact, slab, phi, dist, result, vanished);
    // d was made exact where each rank's band reached: the ghost rows take the
    // owners' values (the next run interpolates them; the blocks share a row).
    slab.exchange(dist);
    ctx.interrupter().end();
    if (vanished && run == 1 && nextOutsideFactor(outsideFactor) > 0.0 &&
      nextOutsideFactor(outsideFactor) <= outsideRoom)
    {
      // The initial surface leaked through a hole: start run 1 again from a wider one.
      const double wider = nextOutsideFactor(outsideFactor);
      recover("run 1 lost its zero level set with the automatic K_P = " + std::to_string(outsideFactor) +
          "; restarted with K_P = " + std::to_string(wider),
        ctx, result);
      forgetRun(1, result);
      outsideFactor = wider;
      result.OutsideThresholdFactor = wider;
      run = 0;
      continue;
    }
    if (vanished && run > 1)
    {
      // Keep the last run that held a surface rather than fail (its grid is coarser).
      recover("run " + std::to_string(run) + " lost its zero level set; the result is run " + std::to_string(run - 1) +
          "'s, on its grid (try a smaller eta in later runs, --schedule)",
        ctx, result);
      forgetRun(run, result);
      keep(std::move(previous), std::move(previousDist), previousSlab);
      return Status::ok();
    }
    if (!status.isOk())
    {
      keep(std::move(phi), std::move(dist), slab);
      if (vanished)
      {
        const std::string stray = strayPointAdvice(cloud, ctx);
        return Status::numericalFailure(
          status.message() + "; " + (stray.empty() ? "try a larger K_P or a larger eta" : stray));
      }
      return status;
    }
    if (run < lastRun)
    {
      slab.recordBand(phi, options.GammaFactor * grid.Spacing[0]); // the next run's cut follows this band
      previous = std::move(phi);
      previousDist = std::move(dist);
      previousSlab = slab;
    }
  }
  keep(std::move(phi), std::move(dist), slab);
  return Status::ok();
}

/// Every rank must hold the same plan, made from the whole cloud (each rank's
/// slab boundaries and messages follow from it): its size, h_P, the runs'
/// grids and a checksum of the points, compared over the ranks.
template <int D>
Status samePlanOnEveryRank(const ReconstructionPlan<D>& plan, const Communicator& comm)
{
  std::vector<double> print = { static_cast<double>(plan.Cloud.size()), plan.CloudSpacing,
    static_cast<double>(plan.Grids.Runs.size()), 0.0 };
  for (const auto& p : plan.Cloud.Points)
  {
    for (int a = 0; a < D; ++a)
    {
      print[3] += p[a];
    }
  }
  std::int64_t count[2] = { static_cast<std::int64_t>(plan.Grids.Runs.size()), 0 };
  count[1] = -count[0];
  comm.allReduce(count, 2, ReduceOp::Max);
  if (count[0] == -count[1])
  {
    for (const GridSpec<D>& g : plan.Grids.Runs)
    {
      for (int a = 0; a < D; ++a)
      {
        print.insert(print.end(), { static_cast<double>(g.Dims[a]), g.Origin[a], g.Spacing[a] });
      }
    }
  }
  std::vector<double> low = print, high = print;
  comm.allReduce(low.data(), low.size(), ReduceOp::Min);
  comm.allReduce(high.data(), high.size(), ReduceOp::Max);
  return count[0] == -count[1] && low == high
    ? Status::ok()
    : Status::invalidArgument("the ranks hold different clouds or plans (each needs the whole cloud and the same "
                              "options): give every rank the whole cloud, e.g. a reader that is not split into pieces");
}

} // namespace

template <int D>
Status reconstruct(
  const ReconstructionPlan<D>& plan, const Context& ctx, ReconstructionResult<D>& result, const Communicator& comm)
{
  result = ReconstructionResult<D>{};
  if (!plan.Locator || plan.Grids.Runs.size() != static_cast<size_t>(plan.Options.Runs))
  {
    return Status::invalidArgument("reconstruct: the plan is incomplete (planReconstruction failed or was not called)");
  }
  if (comm.size() > 1)
  {
    SLTK_RETURN_IF_ERROR(samePlanOnEveryRank(plan, comm));
  }
  const auto runWith = [&](const ReconstructionOptions& options, const std::vector<GridSpec<D>>& grids)
  {
    result.OutsideThresholdFactor = options.OutsideThresholdFactor;
    result.CellSizeFactor = options.CellSizeFactor;
    return withReconstructionInterpolator<D>(options,
      [&](auto tag)
      { return runAll<D, typename decltype(tag)::type>(plan, options, grids, ctx, comm, result, options.Runs); });
  };
  Status status = runWith(plan.Options, plan.Grids.Runs);
  ReconstructionOptions finer = plan.Options;
  finer.Runs -= 1;
  finer.CellSizeFactor /= 2.0;
  GridPlan<D> finerGrids;
  if (status.isOk() && plan.AutomaticCellSize && finer.Runs >= 1 && !result.Runs.empty() &&
    result.Runs.back().FarPoints > FarPointWarning &&
    comm.agree(planRunGrids(plan, finer.Runs, finer.CellSizeFactor, finerGrids)).isOk()) // machines differ
  {
    // Run 1 lost features thinner than its cells: start at half the cell size with
    // one run fewer, which ends on the same finest grid (the same memory).
    std::ostringstream what;
    what << 100.0 * result.Runs.back().FarPoints
         << "% of the points ended more than one cell of run 1 from the surface with C_dx = "
         << plan.Options.CellSizeFactor << ": reconstructed again from C_dx = " << finer.CellSizeFactor << " with "
         << finer.Runs << " run(s), which end on the same finest grid";
    ctx.logger().log(LogLevel::Warning, what.str());
    std::vector<std::string> recoveries = std::move(result.Recoveries);
    recoveries.push_back(what.str());
    result = ReconstructionResult<D>{};
    status = runWith(finer, finerGrids.Runs);
    result.Recoveries.insert(result.Recoveries.begin(), recoveries.begin(), recoveries.end());
  }
  result.CloudSpacing = plan.userCloudSpacing();
  result.Cleaning = plan.Cleaning;
  result.Choices = plan.Choices;
  recordsToUser(plan.Box, result);
  plan.Box.toUser(result.SignedDistance);
  plan.Box.toUser(result.Distance);
  result.WholeGrid = plan.Box.toUser(result.WholeGrid);
  return status;
}

template <int D>
Status reconstructFirstRuns(const ReconstructionPlan<D>& plan, int runs, const Context& ctx,
  ReconstructionResult<D>& result, const Communicator& comm)
{
  result = ReconstructionResult<D>{};
  if (!plan.Locator || runs < 1 || runs > plan.Options.Runs ||
    plan.Grids.Runs.size() != static_cast<size_t>(plan.Options.Runs))
  {
    return Status::invalidArgument("reconstructFirstRuns: the plan is incomplete or has fewer runs than asked");
  }
  if (comm.size() > 1)
  {
    SLTK_RETURN_IF_ERROR(samePlanOnEveryRank(plan, comm));
  }
  result.OutsideThresholdFactor = plan.Options.OutsideThresholdFactor;
  result.CellSizeFactor = plan.Options.CellSizeFactor;
  result.CloudSpacing = plan.CloudSpacing;
  result.Cleaning = plan.Cleaning;
  result.Choices = plan.Choices;
  return withReconstructionInterpolator<D>(plan.Options,
    [&](auto tag)
    { return runAll<D, typename decltype(tag)::type>(plan, plan.Options, plan.Grids.Runs, ctx, comm, result, runs); });
}

template <int D>
Status reconstruct(
  const PointCloud<D>& cloud, const ReconstructionOptions& options, const Context& ctx, ReconstructionResult<D>& result)
{
  result = ReconstructionResult<D>{};
  ReconstructionPlan<D> plan;
  SLTK_RETURN_IF_ERROR(planReconstruction(cloud, options, ctx, plan));
  return reconstruct(plan, ctx, result);
}

template Status reconstruct(
  const PointCloud<2>&, const ReconstructionOptions&, const Context&, ReconstructionResult<2>&);
template Status reconstruct(
  const PointCloud<3>&, const ReconstructionOptions&, const Context&, ReconstructionResult<3>&);
template Status reconstruct(
  const ReconstructionPlan<2>&, const Context&, ReconstructionResult<2>&, const Communicator&);
template Status reconstructFirstRuns(
  const ReconstructionPlan<2>&, int, const Context&, ReconstructionResult<2>&, const Communicator&);
template Status reconstructFirstRuns(
  const ReconstructionPlan<3>&, int, const Context&, ReconstructionResult<3>&, const Communicator&);
template Status reconstruct(
  const ReconstructionPlan<3>&, const Context&, ReconstructionResult<3>&, const Communicator&);

} // namespace sltk
