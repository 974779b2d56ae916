// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/hjb/PresetRun.h"
#include "sltk/hjb/DistributedHjbSolver.h"
#include "sltk/hjb/HjbSolver.h"

#include "HjbSolverOf.h"
#include "sltk/exec/Memory.h"
#include "sltk/hjb/Presets.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sltk
{

namespace
{
template <int D>
HjbSetup<D> setupOf(HjbPreset preset, Index n, double finalTime);

template <>
HjbSetup<1> setupOf<1>(HjbPreset preset, Index n, double finalTime)
{
  return preset == HjbPreset::Test2SemiConcave ? test2Setup(n) : test3Setup(n, finalTime >= 0.0 ? finalTime : 1.0);
}

template <>
HjbSetup<2> setupOf<2>(HjbPreset preset, Index n, double finalTime)
{
  if (preset == HjbPreset::Test1Rotation)
  {
    return test1Setup(n);
  }
  if (preset == HjbPreset::Test4Quadratic)
  {
    return test4Setup(n);
  }
  return test5Setup(n, finalTime >= 0.0 ? finalTime : 3.0);
}

/// The solver of `base` on the preset's grid, with the user's final time and
/// Courant number. A user cannot choose the RK order (O, the setup's) or the
/// cell cache (automatic) of a preset (PresetRunOptions): both are fixed at
/// compile time (withFixedOrder()), one kernel of (3.7) per interpolator.
/// `slab` (a distributed solve): the window of rows [First, Stop) of the last
/// axis only, at the whole grid's coordinates (GridSpec::Offset).
template <RkOrder O, class Problem>
Status presetSolver(const Problem& base, HjbSetup<Problem::Dim> setup, const PresetRunOptions& options,
  std::unique_ptr<HjbSolver>& solver, const SlabPlan* slab = nullptr)
{
  using Fixed = FixedSchemeProblem<Problem, O>;
  const Fixed problem = withFixedOrder<O>(base);
  if (options.FinalTime >= 0.0)
  {
    setup.Options.FinalTime = options.FinalTime;
  }
  if (options.CourantNumber > 0.0)
  {
    setup.Options.MaxTimeStep = options.CourantNumber * setup.Grid.Spacing[0];
  }
  Index steps = 0;
  double dt = 0.0;
  SLTK_RETURN_IF_ERROR(hjbPlanTimeSteps(setup.Options, steps, dt, true)); // T = 0: the initial datum, no step
  if (slab)
  {
    constexpr int last = Problem::Dim - 1;
    setup.Grid.Offset[last] = slab->First;
    setup.Grid.Dims[last] = slab->Stop - slab->First;
    setup.Grid.Bounds[last] = Boundary::Extrapolate; // a periodic axis' window: its end rows are ghost rows
  }
  const bool reachable = options.Preset == HjbPreset::Test5Zermelo;
  solver = makeHjbSolverOf<Fixed>(
    options.Interpolator, problem, setup.Grid, setup.Options, steps, dt, reachable, Problem::HasExact);
  return madeHjbSolver(solver, options.Interpolator);
}
/// Slabs of the preset's grid over `comm` (DistributedHjbSolver.h); `speed`
/// bounds |f_D| along the last axis over the domain and the controls.
template <RkOrder O, class Problem>
Status distributedPreset(const Problem& base, const HjbSetup<Problem::Dim>& setup, const PresetRunOptions& options,
  double speed, const Communicator& comm, std::unique_ptr<HjbSolver>& solver)
{
  std::unique_ptr<HjbSolver> whole; // the plan: nothing is allocated before the first step
  SLTK_RETURN_IF_ERROR(presetSolver<O>(base, setup, options, whole));
  SlabPlan slab;
  constexpr int last = Problem::Dim - 1;
  SLTK_RETURN_IF_ERROR(
    planSlabs(whole->grid(), speed, whole->timeStep(), comm, slab, setup.Grid.Bounds[last] == Boundary::Periodic));
  std::unique_ptr<HjbSolver> window;
  SLTK_RETURN_IF_ERROR(comm.agree(presetSolver<O>(base, setup, options, window, &slab)));
  ExactSolution exact;
  if constexpr (Problem::HasExact)
  {
    exact = [base](double t, const double* x)
    {
      std::array<double, Problem::Dim> point;
      std::copy(x, x + Problem::Dim, point.begin());
      return base.Exact(t, point);
    };
  }
  solver = makeDistributedSolver(
    std::move(window), comm, whole->grid(), std::move(exact), slab, options.Preset == HjbPreset::Test5Zermelo);
  return Status::ok();
}

Status checkPresetOptions(const PresetRunOptions& options)
{
  HjbGrid grid;
  SLTK_RETURN_IF_ERROR(presetGrid(options.Preset, options.Nodes, grid));
  if (!std::isfinite(options.FinalTime) || !std::isfinite(options.CourantNumber))
  {
    return Status::invalidArgument("final time and Courant number must be finite numbers");
  }
  return Status::ok();
}
} // namespace

Status presetGrid(HjbPreset preset, Index nodes, HjbGrid& grid)
{
  if (nodes < 5 || nodes > 100000)
  {
    return Status::invalidArgument("N = " + std::to_string(nodes) + " nodes per direction: use 5 to 100000");
  }
  switch (preset)
  {
    case HjbPreset::Test2SemiConcave:
    case HjbPreset::Test3Eikonal:
      grid = toHjbGrid(setupOf<1>(preset, nodes, -1.0).Grid);
      return Status::ok();
    case HjbPreset::Test1Rotation:
    case HjbPreset::Test4Quadratic:
    case HjbPreset::Test5Zermelo:
    {
      grid = toHjbGrid(setupOf<2>(preset, nodes, -1.0).Grid);
      const double bytes = 24.0 * static_cast<double>(grid.Dims[0]) * static_cast<double>(grid.Dims[1]);
      const double available = static_cast<double>(availableMemoryBytes());
      if (available > 0.0 && bytes > available)
      {
        return Status::outOfMemory("N = " + std::to_string(nodes) + " needs about " + std::to_string(bytes / 1e9) +
          " GB, more than the memory available: use a smaller N");
      }
      return Status::ok();
    }
  }
  return Status::invalidArgument("unknown preset " + std::to_string(static_cast<int>(preset)) + ": use 1 to 5");
}

Status makePresetSolver(const PresetRunOptions& options, std::unique_ptr<HjbSolver>& solver)
{
  solver.reset();
  SLTK_RETURN_IF_ERROR(checkPresetOptions(options));
  const Index n = options.Nodes;
  const double t = options.FinalTime;
  switch (options.Preset)
  {
    case HjbPreset::Test1Rotation:
      return presetSolver<Test1Order>(test1Problem(), setupOf<2>(options.Preset, n, t), options, solver);
    case HjbPreset::Test2SemiConcave:
      return presetSolver<Test2Order>(test2Problem(), setupOf<1>(options.Preset, n, t), options, solver);
    case HjbPreset::Test3Eikonal:
      return presetSolver<Test3Order>(test3Problem(), setupOf<1>(options.Preset, n, t), options, solver);
    case HjbPreset::Test4Quadratic:
      return presetSolver<Test4Order>(test4Problem(), setupOf<2>(options.Preset, n, t), options, solver);
    case HjbPreset::Test5Zermelo:
      return presetSolver<Test5Order>(test5Problem(), setupOf<2>(options.Preset, n, t), options, solver);
  }
  return Status::invalidArgument("unknown preset");
}

Status makeDistributedPresetSolver(
  const PresetRunOptions& options, const Communicator& comm, std::unique_ptr<HjbSolver>& solver)
{
  if (comm.size() == 1)
  {
    return makePresetSolver(options, solver);
  }
  solver.reset();
  SLTK_RETURN_IF_ERROR(checkPresetOptions(options));
  const Index n = options.Nodes;
  const double t = options.FinalTime;
  constexpr double pi = 3.141592653589793;
  switch (options.Preset) // the speed bounds: |2 pi (x - 1/2)| on [0, 1]; |a| <= pi/2; |a| <= 2; |a| <= 2.2; |a2| <= 1
  {
    case HjbPreset::Test1Rotation:
      return distributedPreset<Test1Order>(test1Problem(), setupOf<2>(options.Preset, n, t), options, pi, comm, solver);
    case HjbPreset::Test2SemiConcave:
      return distributedPreset<Test2Order>(
        test2Problem(), setupOf<1>(options.Preset, n, t), options, pi / 2, comm, solver);
    case HjbPreset::Test4Quadratic:
      return distributedPreset<Test4Order>(
        test4Problem(), setupOf<2>(options.Preset, n, t), options, 2.2, comm, solver);
    case HjbPreset::Test5Zermelo:
      return distributedPreset<Test5Order>(
        test5Problem(), setupOf<2>(options.Preset, n, t), options, 1.0, comm, solver);
    case HjbPreset::Test3Eikonal:
      return distributedPreset<Test3Order>(
        test3Problem(), setupOf<1>(options.Preset, n, t), options, 2.0, comm, solver);
  }
  return Status::invalidArgument("unknown preset");
}

} // namespace sltk
