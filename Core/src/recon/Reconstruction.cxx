// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/recon/Reconstruction.h"

#include "sltk/interp/Interpolators.h"
#include "sltk/levelset/NarrowBand.h"
#include "sltk/levelset/Reinitialise.h"
#include "sltk/recon/CloudInitialData.h"
#include "sltk/cloud/CloudSpacing.h"
#include "sltk/recon/DistanceFunction.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/ExactDistanceCache.h"
#include "sltk/recon/GridPlan.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/cloud/PointLocator.h"

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

/// Err_P (4.35): mean |I[phi](Q)| over the cloud (phi's ghosts filled).
template <int D, class Interp>
double cloudError(const GridField<D>& phi, const PointCloud<D>& cloud, const Context& ctx)
{
  const double sum = ctx.parallelSum(0, cloud.size(), [&](Index b, Index e) {
    Interp interp(phi);
    double s = 0.0;
    for (Index k = b; k < e; ++k)
    {
      s += std::fabs(interpolate(interp, phi.spec(), cloud.Points[static_cast<size_t>(k)].data()));
    }
    return s;
  });
  return sum / static_cast<double>(cloud.size());
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

/// eps_1^n of (4.34) restricted to `nodes`: sum |phi^{n+1} - phi^n| / sum |phi^n|,
/// with phi^{n+1} the iterate after reinitialisation and cut and `before` = phi^n
/// at the same nodes (gatherValues). Nodes outside the set did not change.
template <int D>
double updateNorm(const GridField<D>& phi, const NodeList& nodes, const std::vector<double>& before)
{
  double moved = 0.0, size = 0.0;
  for (size_t k = 0; k < nodes.size(); ++k)
  {
    moved += std::fabs(phi(phi.nodeIndex(nodes[k])) - before[k]);
    size += std::fabs(before[k]);
  }
  return size > 0.0 ? moved / size : 0.0;
}

/// The previous run's phi (ghosts filled) interpolated at the nodes of `grid` (Q1: monotone).
template <int D>
void transfer(const GridField<D>& from, const GridSpec<D>& grid, const Context& ctx, GridField<D>& to)
{
  to.resize(grid, PhiGhost);
  ctx.parallelFor(0, grid.nodeCount(), [&](Index b, Index e) {
    Q1Interpolator<D> interp(from);
    for (Index k = b; k < e; ++k)
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
}

/// The stopping rule (4.33): Delta_E^n = |ebar_{n-1} - ebar_n| / ebar_n with the
/// mean ebar_n of the last k = min(n, window) energies E_2.
bool energyStalled(const std::vector<double>& energies, int window, double tolerance)
{
  const int n = static_cast<int>(energies.size());
  if (n < 2)
  {
    return false;
  }
  const int k = std::min(n - 1, window);
  double now = 0.0, before = 0.0;
  for (int j = 0; j < k; ++j)
  {
    now += energies[static_cast<size_t>(n - 1 - j)];
    before += energies[static_cast<size_t>(n - 2 - j)];
  }
  now /= k;
  before /= k;
  return now > 0.0 && std::fabs(before - now) / now < tolerance;
}

/// The iterations of one run on its grid (Algorithm 1, step 4).
template <int D, class Interp>
Status iterate(const PointCloud<D>& cloud, const ReconstructionOptions& options, int run, const Context& ctx,
  ExactDistanceCache<D>& exact, GridField<D>& phi, GridField<D>& dist, ReconstructionResult<D>& result)
{
  const auto start = std::chrono::steady_clock::now();
  const GridSpec<D>& grid = phi.spec();
  const double dx = grid.Spacing[0];
  const RunParameters model = options.parameters(run);
  LevelSetStepParameters step;
  step.P = model.P;
  step.Eta = model.Eta;
  step.TimeStep = dx; // (4.36): dt = dx
  step.Widths = BandWidths::forSpacing(dx, options.BetaFactor, options.GammaFactor);
  // h_P in the unit box: dx = C_dx h_P / 2^(run-1) (4.36).
  const double cloudSpacing = options.CellSizeFactor > 0.0 ? dx * std::ldexp(1.0, run - 1) / options.CellSizeFactor : dx;
  step.DetectTunnels = options.DetectTunnels;
  step.TunnelDistance = 2.0 * dx; // 4.5.6
  step.TunnelMinDistance = 0.6 * cloudSpacing;
  const double gamma = step.Widths.Gamma;

  RunRecord<D> record;
  record.Grid = grid;
  record.Parameters = model;
  NodeList band, reinitBand;
  std::vector<std::uint8_t> dilationScratch;
  std::vector<double> stepScratch, previousValues;
  std::vector<double> energies;
  double bandSizes = 0.0;
  double phase[4] = { 0.0, 0.0, 0.0, 0.0 }; // energy, step, reinitialisation, metrics (seconds)
  collectBand(phi, gamma, ctx, band); // (1.50)
  exact.reset(dist);
  for (int n = 0; n < options.MaxIterations; ++n)
  {
    exact.ensure(band, ctx, dist);
    // (4.29)/(4.30) on the cells of the band: E_p for the scale factor, E_2 for (4.33).
    auto clock = std::chrono::steady_clock::now();
    EnergyResult ep;
    EnergyOptions energyOptions;
    energyOptions.P = model.P;
    energyOptions.SecondP = model.P != 2.0 ? 2.0 : 0.0; // E_2 in the same pass
    SLTK_RETURN_IF_ERROR(energyFunctional(phi, dist, band, ctx, ep, energyOptions));
    EnergyResult e2 = ep;
    if (model.P != 2.0)
    {
      e2.Integral = ep.SecondIntegral;
      e2.Energy = ep.SecondEnergy;
    }
    if (ep.FrontCells == 0)
    {
      return Status::numericalFailure("run " + std::to_string(run) +
        ": the zero level set vanished (no front cell); try a larger K_P or a larger eta");
    }
    energies.push_back(e2.Energy);
    if (n >= options.MinIterations && energyStalled(energies, options.EnergyWindow, options.Tolerance))
    {
      break;
    }
    step.Energy = ep.Energy;
    phase[0] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();
    // The step writes the band, the reinitialisation its dilation (1.53): phi^n there for eps_1 (4.34).
    dilateBand(grid, band, options.ReinitDilation, dilationScratch, reinitBand);
    gatherValues(phi, reinitBand, previousValues);
    SLTK_RETURN_IF_ERROR((levelSetStep<Interp, D>(ctx, phi, dist, band, step, stepScratch))); // (4.22)/(4.24)
    phase[1] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();
    SLTK_RETURN_IF_ERROR(reinitialise<D>(phi, reinitBand, options.Reinit, ctx));
    cutLevelSet(phi, reinitBand, gamma, ctx); // (1.49)
    phi.fillGhosts();
    filterBand(phi, reinitBand, gamma, ctx, band); // (1.54)
    phase[2] += secondsSince(clock);
    clock = std::chrono::steady_clock::now();

    IterationRecord it;
    it.Run = run;
    it.Iteration = n + 1;
    it.Energy = e2.Energy;
    it.Change = updateNorm(phi, reinitBand, previousValues); // (4.34) between successive iterates
    it.CloudError = cloudError<D, Interp>(phi, cloud, ctx);
    it.BandSize = static_cast<Index>(band.size());
    it.Seconds = secondsSince(start);
    result.History.push_back(it);
    record.Iterations = n + 1;
    record.Energy = it.Energy;
    record.CloudError = it.CloudError;
    bandSizes += static_cast<double>(band.size());
    phase[3] += secondsSince(clock);

    const double fraction = (run - 1 + double(n + 1) / options.MaxIterations) / options.Runs;
    if (ctx.interrupter().wasInterrupted(fraction))
    {
      result.Runs.push_back(record);
      return Status::aborted();
    }
  }
  record.Seconds = secondsSince(start);
  record.MeanBandSize = record.Iterations ? static_cast<Index>(bandSizes / record.Iterations) : 0;
  if (record.Iterations == 0)
  {
    record.Energy = energies.empty() ? 0.0 : energies.back();
    phi.fillGhosts();
    record.CloudError = cloudError<D, Interp>(phi, cloud, ctx);
  }
  const double spacing = cloudSpacing;
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

/// Initial data of a run: run 1 from the cloud (4.4.4) or an ellipsoid, later
/// runs from the previous result; cut (1.49) and made a distance near the front.
template <int D>
Status initialData(const PointCloud<D>& cloud, const ReconstructionOptions& options, int run, double spacing,
  const GridField<D>& dist, const GridField<D>* previous, const Context& ctx, GridField<D>& phi)
{
  const GridSpec<D>& grid = dist.spec();
  const double gamma = options.GammaFactor * grid.Spacing[0];
  if (previous)
  {
    transfer(*previous, grid, ctx, phi);
  }
  else if (options.Guess == InitialGuess::OutsideMarking)
  {
    InitialDataOptions io;
    io.Ghost = PhiGhost;
    SLTK_RETURN_IF_ERROR(cloudInitialData(dist, options.OutsideThresholdFactor * spacing, ctx, phi, io));
  }
  else
  {
    const double margin = options.OutsideThresholdFactor * spacing;
    const Ellipsoid<D> e = options.Guess == InitialGuess::BoundingSphere ? boundingSphere(cloud, margin)
                                                                         : boundingEllipsoid(cloud, margin);
    SLTK_RETURN_IF_ERROR(ellipsoidLevelSet(e, grid, ctx, phi, PhiGhost));
  }
  cutLevelSet(phi, gamma, ctx);
  if (previous)
  {
    NodeList band, wide;
    std::vector<std::uint8_t> scratch;
    collectBand(phi, gamma, ctx, band);
    dilateBand(grid, band, options.ReinitDilation, scratch, wide);
    SLTK_RETURN_IF_ERROR(reinitialise<D>(phi, wide, options.Reinit, ctx));
    cutLevelSet(phi, wide, gamma, ctx);
  }
  phi.fillGhosts();
  return Status::ok();
}

template <int D, class Interp>
Status runAll(const PointCloud<D>& cloud, const ReconstructionOptions& options, const GridPlan<D>& plan,
  const Context& ctx, ReconstructionResult<D>& result)
{
  // Coarser buckets than the locator's default (2 points): the first bands of run 1
  // lie K_P h_P (4.4.4) from the cloud, where a fine bucket grid makes every
  // nearest-point query scan thousands of empty buckets (K_P = 16 on merged
  // scans: run 1 took 40% less time); the distances are the same exact ones.
  const PointLocator<D> locator(cloud, 16.0);
  ExactDistanceCache<D> exact(cloud, locator);
  GridField<D> phi, previous, dist, previousDist;
  for (int run = 1; run <= options.Runs; ++run)
  {
    const GridSpec<D>& grid = plan.Runs[static_cast<size_t>(run - 1)];
    ctx.interrupter().start("run " + std::to_string(run) + "/" + std::to_string(options.Runs));
    const auto setup = std::chrono::steady_clock::now();
    if (run == 1)
    {
      DistanceOptions dopt;
      dopt.Ghost = PhiGhost;
      SLTK_RETURN_IF_ERROR(distanceToCloud(cloud, grid, ctx, dist, dopt)); // (4.4.2)
    }
    else
    {
      // Later runs: d interpolated from the previous run; exact values follow the band.
      transfer(previousDist, grid, ctx, dist);
      dist.fillGhosts();
      previousDist = GridField<D>();
    }
    const double distanceSeconds = secondsSince(setup);
    SLTK_RETURN_IF_ERROR(initialData(cloud, options, run, plan.CloudSpacing, dist, run > 1 ? &previous : nullptr,
      ctx, phi));
    previous = GridField<D>(); // free the coarse field before iterating
    std::ostringstream log;
    log << "run " << run << ": grid " << grid.nodeCount() << " nodes, distance " << distanceSeconds
        << " s, initial data " << secondsSince(setup) - distanceSeconds << " s";
    ctx.logger().log(LogLevel::Info, log.str());
    const Status status = iterate<D, Interp>(cloud, options, run, ctx, exact, phi, dist, result);
    ctx.interrupter().end();
    if (!status.isOk())
    {
      result.SignedDistance = std::move(phi);
      result.Distance = std::move(dist);
      return status;
    }
    if (run < options.Runs)
    {
      previous = std::move(phi);
      previousDist = std::move(dist);
    }
  }
  result.SignedDistance = std::move(phi);
  result.Distance = std::move(dist);
  return Status::ok();
}

/// The thesis rescales every cloud into [-1, 1]^d (4.5): the model (4.9) is
/// not scale-invariant for p > 1 (d / E_p has the dimension of 1/length).
template <int D>
struct UnitBox
{
  std::array<double, D> Centre{};
  double Scale = 1.0; ///< user length = Scale * unit-box length

  explicit UnitBox(const Box<D>& box)
  {
    double half = 0.0;
    for (int a = 0; a < D; ++a)
    {
      this->Centre[a] = 0.5 * (box.Min[a] + box.Max[a]);
      half = std::max(half, 0.5 * box.extent(a));
    }
    this->Scale = half;
  }

  PointCloud<D> toUnit(const PointCloud<D>& cloud) const
  {
    PointCloud<D> unit;
    unit.Points.resize(cloud.Points.size());
    for (size_t k = 0; k < cloud.Points.size(); ++k)
    {
      for (int a = 0; a < D; ++a)
      {
        unit.Points[k][a] = (cloud.Points[k][a] - this->Centre[a]) / this->Scale;
      }
    }
    return unit;
  }

  GridSpec<D> toUser(GridSpec<D> g) const
  {
    for (int a = 0; a < D; ++a)
    {
      g.Origin[a] = this->Centre[a] + this->Scale * g.Origin[a];
      g.Spacing[a] *= this->Scale;
    }
    return g;
  }

  /// Lengths (phi, d) and the grid back to the user's units.
  void toUser(GridField<D>& f) const
  {
    const GridSpec<D> g = this->toUser(f.spec());
    f.setGeometry(g.Origin, g.Spacing);
    for (double& v : f.storage())
    {
      v *= this->Scale;
    }
  }
};

/// Records of a unit-box run in the user's units: E_2 ~ length^((2 + D - 1) / 2).
template <int D>
void recordsToUser(const UnitBox<D>& box, ReconstructionResult<D>& result)
{
  const double energyScale = std::pow(box.Scale, (2.0 + D - 1.0) / 2.0);
  for (auto& it : result.History)
  {
    it.Energy *= energyScale;
    it.CloudError *= box.Scale;
  }
  for (auto& run : result.Runs)
  {
    run.Grid = box.toUser(run.Grid);
    run.Energy *= energyScale;
    run.CloudError *= box.Scale;
  }
  result.CloudSpacing *= box.Scale;
  box.toUser(result.SignedDistance);
  box.toUser(result.Distance);
}

template <int D>
Status reconstructInUnitBox(const PointCloud<D>& cloud, const ReconstructionOptions& options, const Context& ctx,
  ReconstructionResult<D>& result)
{
  if (options.Runs < 1 || options.MaxIterations < 1 || options.MinIterations < 0 || options.EnergyWindow < 1 ||
    !(options.OutsideThresholdFactor > 0.0) || !(options.Tolerance >= 0.0) || options.ReinitDilation < 1 ||
    !(options.BetaFactor > 0.0) || !(options.GammaFactor > options.BetaFactor))
  {
    return Status::invalidArgument("reconstruction options out of range: need runs >= 1, iterations >= 1, "
                                   "K_P > 0, tolerance >= 0, 0 < beta < gamma");
  }
  SLTK_RETURN_IF_ERROR(validateSchedule(options.Schedule));
  SLTK_RETURN_IF_ERROR(options.Reinit.validate<D>());
  double spacing = 0.0;
  SLTK_RETURN_IF_ERROR(cloudSpacing(cloud, ctx, spacing)); // h_P (4.36)
  GridPlanOptions po;
  po.Runs = options.Runs;
  po.CellSizeFactor = options.CellSizeFactor;
  po.Padding = options.Padding;
  // Run 1 must hold the initial surface, K_P h_P outside the cloud (4.4.4) or the
  // ellipsoid around it, plus the band gamma and two cells, inside the grid.
  const Box<D> bounds = boundingBox(cloud);
  const double dx1 = options.CellSizeFactor * spacing;
  double reach = options.OutsideThresholdFactor * spacing;
  if (options.Guess != InitialGuess::OutsideMarking)
  {
    const double margin = options.OutsideThresholdFactor * spacing;
    const Ellipsoid<D> e = options.Guess == InitialGuess::BoundingSphere ? boundingSphere(cloud, margin)
                                                                         : boundingEllipsoid(cloud, margin);
    for (int a = 0; a < D; ++a)
    {
      reach = std::max(reach, e.Centre[a] + e.SemiAxes[a] - bounds.Max[a]);
      reach = std::max(reach, bounds.Min[a] - (e.Centre[a] - e.SemiAxes[a]));
    }
  }
  po.FirstRunPadding = static_cast<int>(std::ceil(reach / dx1 + options.GammaFactor + 2.0));
  po.BytesPerNode = 40.0; // phi and d with ghosts, band masks, the coarse field during transfer
  po.MemoryBudget = options.MemoryBudget;
  GridPlan<D> plan;
  SLTK_RETURN_IF_ERROR(planGrids(bounds, spacing, po, plan));
  result.CloudSpacing = spacing;
  return withInterpolator<D>(options.Interpolator, [&](auto tag) {
    return runAll<D, typename decltype(tag)::type>(cloud, options, plan, ctx, result);
  });
}
} // namespace

Status validateSchedule(const std::vector<RunParameters>& schedule)
{
  for (size_t k = 0; k < schedule.size(); ++k)
  {
    const RunParameters& run = schedule[k];
    if (!(run.P >= 1.0 && run.P <= 10.0) || !(run.Eta >= 0.0 && run.Eta <= 100.0))
    {
      std::ostringstream m;
      m << "run schedule pair " << k + 1 << " (p = " << run.P << ", eta = " << run.Eta
        << ") out of range: the model (4.9) needs 1 <= p <= 10 and 0 <= eta <= 100";
      return Status::invalidArgument(m.str());
    }
  }
  return Status::ok();
}

template <int D>
Status reconstruct(const PointCloud<D>& userCloud, const ReconstructionOptions& options, const Context& ctx,
  ReconstructionResult<D>& result)
{
  result = ReconstructionResult<D>{};
  SLTK_RETURN_IF_ERROR(validateCloud(userCloud));
  // Cleaning comes before the unit box (4.5): an outlier would otherwise set its scale.
  PointCloud<D> cleaned;
  SLTK_RETURN_IF_ERROR(cleanCloud(userCloud, options.Cleaning, ctx, cleaned, result.Cleaning));
  const Status valid = validateCloud(cleaned);
  if (!valid.isOk())
  {
    return Status::invalidArgument("after cleaning: " + valid.message() + "; relax outlier removal or thinning");
  }
  const UnitBox<D> box(boundingBox(cleaned));
  const PointCloud<D> cloud = box.toUnit(cleaned);
  cleaned = PointCloud<D>();
  const Status status = reconstructInUnitBox(cloud, options, ctx, result);
  recordsToUser(box, result);
  return status;
}


template Status reconstruct(
  const PointCloud<2>&, const ReconstructionOptions&, const Context&, ReconstructionResult<2>&);
template Status reconstruct(
  const PointCloud<3>&, const ReconstructionOptions&, const Context&, ReconstructionResult<3>&);

} // namespace sltk
