// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/hjb/PresetRun.h"

#include "sltk/exec/Memory.h"
#include "sltk/hjb/HjbError.h"
#include "sltk/hjb/Presets.h"
#include "sltk/interp/Cweno.h"
#include "sltk/interp/Q1.h"
#include "sltk/interp/Weno3.h"

#include <cmath>

namespace sltk
{

namespace
{
template <int D>
PresetGrid toPresetGrid(const GridSpec<D>& g)
{
  PresetGrid p;
  p.Dimension = D;
  for (int a = 0; a < D; ++a)
  {
    p.Dims[a] = g.Dims[a];
    p.Origin[a] = g.Origin[a];
    p.Spacing[a] = g.Spacing[a];
  }
  for (int a = D; a < 3; ++a)
  {
    p.Spacing[a] = g.Spacing[0];
  }
  return p;
}

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

template <class Interp, class Problem>
Status solve(const Problem& problem, HjbSetup<Problem::Dim> setup, const PresetRunOptions& options,
  const Context& ctx, PresetRunResult& result)
{
  constexpr int D = Problem::Dim;
  if (options.FinalTime >= 0.0)
  {
    setup.Options.FinalTime = options.FinalTime;
  }
  if (options.CourantNumber > 0.0)
  {
    setup.Options.MaxTimeStep = options.CourantNumber * setup.Grid.Spacing[0];
  }
  result.FinalTime = setup.Options.FinalTime;
  GridField<D> u(setup.Grid, Interp::GhostWidth);
  hjbInitialize(problem, u);
  GridField<D> reach;
  const bool reachable = options.Preset == HjbPreset::Test5Zermelo;
  HjbStats stats;
  if (setup.Options.FinalTime > setup.Options.StartTime)
  {
    SLTK_RETURN_IF_ERROR(
      (hjbAdvance<Interp>(ctx, setup.Options, problem, u, &stats, reachable ? &reach : nullptr, &result.Steps)));
  }
  result.EvaluationsPerNode = stats.evaluationsPerNode();
  result.Grid = toPresetGrid(setup.Grid);
  const Index n = setup.Grid.nodeCount();
  result.Value.resize(static_cast<size_t>(n));
  for (Index k = 0; k < n; ++k)
  {
    result.Value[static_cast<size_t>(k)] = u(u.nodeIndex(k));
  }
  if (reachable)
  {
    result.ReachTime.assign(static_cast<size_t>(n), NotReached);
    if (reach.spec().nodeCount() == n)
    {
      for (Index k = 0; k < n; ++k)
      {
        result.ReachTime[static_cast<size_t>(k)] = reach(reach.nodeIndex(k));
      }
    }
  }
  if constexpr (Problem::HasExact)
  {
    const double t = result.FinalTime;
    result.L1Error = l1Error(u, [&](const std::array<double, D>& x) { return problem.Exact(t, x); });
    double worst = 0.0;
    for (Index k = 0; k < n; ++k)
    {
      const auto i = u.nodeIndex(k);
      std::array<double, D> x;
      for (int a = 0; a < D; ++a)
      {
        x[a] = setup.Grid.coordinate(a, i[a]);
      }
      worst = std::max(worst, std::fabs(u(i) - problem.Exact(t, x)));
    }
    result.LinfError = worst;
  }
  return Status::ok();
}

template <class Problem>
Status dispatch(const Problem& problem, const HjbSetup<Problem::Dim>& setup, const PresetRunOptions& options,
  const Context& ctx, PresetRunResult& result)
{
  constexpr int D = Problem::Dim;
  switch (options.Interpolator)
  {
    case InterpolatorKind::Q1:
      return solve<Q1Interpolator<D>>(problem, setup, options, ctx, result);
    case InterpolatorKind::Weno3:
      return solve<Weno3Interpolator<D>>(problem, setup, options, ctx, result);
    case InterpolatorKind::Cweno:
      return solve<CwenoInterpolator<D>>(problem, setup, options, ctx, result);
    case InterpolatorKind::CwenoZ:
      return solve<CwenoZInterpolator<D>>(problem, setup, options, ctx, result);
  }
  return Status::invalidArgument("unknown interpolator");
}
} // namespace

Status presetGrid(HjbPreset preset, Index nodes, PresetGrid& grid)
{
  if (nodes < 5 || nodes > 100000)
  {
    return Status::invalidArgument("N = " + std::to_string(nodes) + " nodes per direction: use 5 to 100000");
  }
  switch (preset)
  {
    case HjbPreset::Test2SemiConcave:
    case HjbPreset::Test3Eikonal:
      grid = toPresetGrid(setupOf<1>(preset, nodes, -1.0).Grid);
      return Status::ok();
    case HjbPreset::Test1Rotation:
    case HjbPreset::Test4Quadratic:
    case HjbPreset::Test5Zermelo:
    {
      grid = toPresetGrid(setupOf<2>(preset, nodes, -1.0).Grid);
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

Status runPreset(const PresetRunOptions& options, const Context& ctx, PresetRunResult& result)
{
  result = PresetRunResult{};
  PresetGrid grid;
  SLTK_RETURN_IF_ERROR(presetGrid(options.Preset, options.Nodes, grid));
  if (!std::isfinite(options.FinalTime) || !std::isfinite(options.CourantNumber))
  {
    return Status::invalidArgument("final time and Courant number must be finite numbers");
  }
  const Index n = options.Nodes;
  const double t = options.FinalTime;
  switch (options.Preset)
  {
    case HjbPreset::Test1Rotation:
      return dispatch(test1Problem(), setupOf<2>(options.Preset, n, t), options, ctx, result);
    case HjbPreset::Test2SemiConcave:
      return dispatch(test2Problem(), setupOf<1>(options.Preset, n, t), options, ctx, result);
    case HjbPreset::Test3Eikonal:
      return dispatch(test3Problem(), setupOf<1>(options.Preset, n, t), options, ctx, result);
    case HjbPreset::Test4Quadratic:
      return dispatch(test4Problem(), setupOf<2>(options.Preset, n, t), options, ctx, result);
    case HjbPreset::Test5Zermelo:
      return dispatch(test5Problem(), setupOf<2>(options.Preset, n, t), options, ctx, result);
  }
  return Status::invalidArgument("unknown preset");
}

} // namespace sltk
