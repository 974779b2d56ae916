// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file RunIterations.h
/// The iterations of one run of Algorithm 1 (thesis 4.5, step 4), written once
/// for every storage of a run's level set: the uniform grid on slabs
/// (Core/src/recon/SlabBand.h), the tiled band (Core/src/octree/TiledBand.h)
/// and the thesis's cell-centred tree (P4est/src/cellcentred/). The loop owns the
/// model's parameters, the stopping rule (4.33) with the far-point extension,
/// the records, the interruption and the run's report; the storage owns where
/// the band's values live and how they are exchanged between ranks.
///
/// A band storage `B` provides (every call collective: each rank returns the
/// same status and the same reduced numbers):
///  - `const GridSpec<D>& grid() const`: the run's whole grid;
///  - `Status prepare()`: the band B^n (1.48) and exact distances where the
///    energy, the step and the reinitialisation read d;
///  - `Status energy(const EnergyOptions&, EnergyResult&)`: E_p (and E_2) of
///    (4.29)/(4.30) over the band, summed over every rank;
///  - `double farFraction(double far)`: the share of the cloud's points with
///    |I[phi](Q)| > far;
///  - `Status step(const LevelSetStepParameters&)`: the SL step (4.22)/(4.24)
///    on B^n, ghost values exchanged;
///  - `Status reinitialise()`: the reinitialisation (1.38)-(1.45) on the
///    dilated band (1.53), the cut (1.49) and the next band (1.54);
///  - `bool measure(IterationRecord&, bool interrupted)`: eps_1 (4.34), Err_P
///    (4.35), the band size and the storage's counts; true when any rank was
///    interrupted;
///  - `Index mergeIsolatedNodes()`: gives the single-node specks of the run's
///    result their neighbours' mean (levelset/IsolatedNodes.h), ghosts
///    exchanged; returns their count over every rank;
///  - `void finish(RunRecord<D>&, double far)`: the far-point share after the
///    last iteration (and Err_P when no iteration ran);
///  - `std::string describe() const`: the storage's part of the run's report.

#include "sltk/exec/Context.h"
#include "sltk/recon/EnergyFunctional.h"
#include "sltk/recon/LevelSetStep.h"
#include "sltk/recon/Reconstruction.h"
#include "sltk/recon/StoppingRule.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace sltk
{

/// The SL step's parameters of run `run` on a grid of spacing dx (unit box):
/// the model's p and eta (Table 4.1 or the schedule), dt = dx (4.36), the band
/// widths (1.48) and the tunnel test of 4.5.6 from h_P (`cloudSpacing`).
inline LevelSetStepParameters runStepParameters(
  const ReconstructionOptions& options, int run, double dx, double cloudSpacing)
{
  const RunParameters model = options.parameters(run);
  LevelSetStepParameters step;
  step.P = model.P;
  step.Eta = model.Eta;
  step.TimeStep = dx; // (4.36): dt = dx
  step.Widths = BandWidths::forSpacing(dx, options.BetaFactor, options.GammaFactor);
  step.DetectTunnels = options.DetectTunnels;
  step.TunnelDistance = 2.0 * dx; // 4.5.6
  step.TunnelMinDistance = 0.6 * cloudSpacing;
  if (options.FeetWithinBeta)
  {
    step.FeetWithin = step.Widths.Beta;
  }
  return step;
}

/// A point is far from run `run`'s surface beyond one cell of run 1, C_dx h_P
/// (4.36), and at least h_P (StoppingRule.h). phi is cut at +-gamma (1.49), and
/// from run 3 on one run-1 cell is gamma exactly (gamma = 4 dx): a point beyond
/// the band reads |I[phi](Q)| = gamma at most and counts as far only by the
/// interpolator's overshoot. Counting it (a threshold just below gamma) made the
/// teapot's spout restart into 5 pieces (Documentation/Numerics.md, "Points
/// beyond the band"), so the far points keep this definition for now; the
/// misfit (below) counts them.
inline double farPointDistance(double dx, int run, double cloudSpacing)
{
  return std::max(dx * std::ldexp(1.0, run - 1), cloudSpacing);
}

namespace detail
{
inline double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Seconds per phase of a run's iterations (the profile in its report).
struct IterationPhases
{
  double Band = 0.0, Energy = 0.0, Step = 0.0, Reinitialisation = 0.0, Metrics = 0.0;
};

/// The run's warning when its surface did not reach the cloud (the far points
/// are told after the recoveries, reconstructWithRecoveries).
template <int D>
void warnAboutRun(const RunRecord<D>& record, int run, double cloudSpacing, const Context& ctx)
{
  if (record.CloudError > 2.0 * cloudSpacing)
  {
    std::ostringstream warning;
    warning << "run " << run << " ended with Err_P = " << record.CloudError / cloudSpacing
            << " h_P: the surface did not reach the cloud; try a larger K_P (holes), a larger eta or a smaller C_dx";
    ctx.logger().log(LogLevel::Warning, warning.str());
  }
}

template <int D>
void reportRun(
  const RunRecord<D>& record, int run, const IterationPhases& p, const std::string& storage, const Context& ctx)
{
  std::ostringstream log;
  log << "run " << run << ": " << record.Iterations << " iterations, E_2 = " << record.Energy
      << ", Err_P = " << record.CloudError << ", " << record.Seconds << " s (band " << p.Band << " s, energy "
      << p.Energy << " s, SL step " << p.Step << " s, reinitialisation " << p.Reinitialisation << " s, metrics "
      << p.Metrics << " s)" << storage;
  if (record.MergedNodes > 0)
  {
    log << "; " << record.MergedNodes << " single-node specks merged";
  }
  ctx.logger().log(LogLevel::Info, log.str());
}
} // namespace detail

/// The iterations of run `run` (Algorithm 1, step 4) on `band`'s storage, with
/// h_P = `cloudSpacing` (unit box): until the rule (4.33) holds, beyond it
/// while FollowFarPoints sees the far points still approaching, or
/// MaxIterations. One IterationRecord per iteration and the RunRecord go to
/// `result`; `vanished` tells a zero level set that vanished (the caller's
/// recoveries). Collective: every rank takes every decision from the same
/// reduced numbers.
template <int D, class Band>
Status iterateRun(Band& band, const ReconstructionOptions& options, int run, double cloudSpacing, const Context& ctx,
  ReconstructionResult<D>& result, bool& vanished)
{
  using Clock = std::chrono::steady_clock;
  using detail::secondsSince;
  vanished = false;
  const auto start = Clock::now();
  const double dx = band.grid().Spacing[0];
  const RunParameters model = options.parameters(run);
  LevelSetStepParameters step = runStepParameters(options, run, dx, cloudSpacing);
  const double far = farPointDistance(dx, run, cloudSpacing);
  double checkedFar = -1.0; // FollowFarPoints: the fraction at the last check, and when to check again
  int nextFarCheck = 0;
  EnergyOptions energyOptions;
  energyOptions.P = model.P;
  energyOptions.SecondP = model.P != 2.0 ? 2.0 : 0.0; // E_2 in the same pass

  RunRecord<D> record;
  record.Grid = band.grid();
  record.Parameters = model;
  std::vector<double> energies;
  double bandSizes = 0.0;
  detail::IterationPhases phases;
  for (int n = 0; n < options.MaxIterations; ++n)
  {
    auto clock = Clock::now();
    SLTK_RETURN_IF_ERROR(band.prepare());
    phases.Band += secondsSince(clock);
    clock = Clock::now();
    // (4.29)/(4.30) on the cells of the band: E_p for the scale factor (4.32), E_2 for (4.33).
    EnergyResult ep;
    SLTK_RETURN_IF_ERROR(band.energy(energyOptions, ep));
    if (ep.FrontCells == 0)
    {
      vanished = true;
      return Status::numericalFailure("run " + std::to_string(run) + ": the zero level set vanished (no front cell)");
    }
    energies.push_back(model.P != 2.0 ? ep.SecondEnergy : ep.Energy);
    if (n >= options.MinIterations && energyStalled(energies, options.EnergyWindow, options.Tolerance) &&
      n >= nextFarCheck)
    {
      if (!options.FollowFarPoints)
      {
        break;
      }
      // Beyond the thesis: stalled by (4.33), but still approaching far points?
      const double fraction = band.farFraction(far);
      if (!stillApproaching(fraction, checkedFar))
      {
        break;
      }
      checkedFar = fraction;
      nextFarCheck = n + options.EnergyWindow;
    }
    step.Energy = ep.Energy;
    phases.Energy += secondsSince(clock);
    clock = Clock::now();
    SLTK_RETURN_IF_ERROR(band.step(step)); // (4.22)/(4.24)
    phases.Step += secondsSince(clock);
    clock = Clock::now();
    SLTK_RETURN_IF_ERROR(band.reinitialise()); // (1.38)-(1.45), (1.49), (1.54)
    phases.Reinitialisation += secondsSince(clock);
    clock = Clock::now();

    IterationRecord it;
    it.Run = run;
    it.Iteration = n + 1;
    it.Energy = energies.back();
    const double progress = (run - 1 + double(n + 1) / options.MaxIterations) / options.Runs;
    const bool interrupted = band.measure(it, ctx.interrupter().wasInterrupted(progress));
    it.Seconds = secondsSince(start);
    result.History.push_back(it);
    record.Iterations = n + 1;
    record.Energy = it.Energy;
    record.CloudError = it.CloudError;
    bandSizes += static_cast<double>(it.BandSize);
    phases.Metrics += secondsSince(clock);
    if (interrupted) // every rank stops
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
  }
  record.MergedNodes = band.mergeIsolatedNodes(); // below the grid's resolution (IsolatedNodes.h)
  band.finish(record, far);
  // Often the far-point distance: no second pass then.
  const double misfit = misfitThreshold(dx, cloudSpacing, options.GammaFactor);
  record.MisfitPoints = misfit == far ? record.FarPoints : band.farFraction(misfit);
  detail::warnAboutRun(record, run, cloudSpacing, ctx);
  detail::reportRun(record, run, phases, band.describe(), ctx);
  result.Runs.push_back(record);
  return Status::ok();
}

} // namespace sltk
