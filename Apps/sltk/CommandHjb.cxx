// SPDX-License-Identifier: BSD-3-Clause
// `sltk hjb`: the HJB solver (vtkCWENOHJBSolver) from a terminal.
#include "Commands.h"
#include "ErrorCollector.h"
#include "HjbCustomProblem.h"
#include "Json.h"
#include "WriteAtomically.h"
#include "WriteSurface.h"

#include "sltk/exec/Memory.h"
#include "sltk/interp/InterpolatorKind.h"

#include <vtkCWENOHJBSolver.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <chrono>
#include <iostream>

namespace sltkcli
{

namespace
{
const char* hjbUsage = R"(usage: sltk hjb [options]

Solves a Hamilton-Jacobi-Bellman problem with the semi-Lagrangian scheme (3.7)
(Preda 2024, ch. 3): the thesis's Tests 1-5 with their domains, controls, RK
orders and time steps, or a problem given by formulas (below).

options:
  --preset NAME          test1 (rotation, 2D) | test2 (semi-concave, 1D) | test3 (eikonal, 1D periodic)
                         | test4 (quadratic, 2D) | test5 (Zermelo with obstacles, 2D)   (default test1)
  --n N                  preset: nodes per direction (default 81)
  --final-time T         final time (default: the preset's; 0 gives the initial datum)
  --courant L            dt = L dx (default: the preset's; custom: 1, dx the smallest spacing)
  --interpolator NAME    q1 | weno3 | cweno | cwenoz (default cwenoz)
  --threads T            threads (default: all)
  -o, --output FILE.vti  write the value function (and ReachTime for test5)
  --json FILE            summary: l1_error, linf_error (when exact), min, max, seconds, steps, evaluations_per_node
)";

} // namespace

int commandHjb(const Args& rawArgs)
{
  Args args = rawArgs;
  for (auto& a : args)
  {
    a = a == "-o" ? "--output" : a;
  }
  std::vector<std::string> valued = { "preset", "n", "final-time", "courant", "interpolator", "threads", "output",
    "json" };
  valued.insert(valued.end(), hjbCustomOptionNames().begin(), hjbCustomOptionNames().end());
  Options opt(args, valued, { "help", "reach" });
  if (opt.has("help"))
  {
    std::cout << hjbUsage << hjbCustomUsage;
    return 0;
  }
  const bool custom = hasHjbCustomProblem(opt);
  const double n = opt.number("n", 81);
  const double finalTime = opt.number("final-time", -1.0);
  const double courant = opt.number("courant", 0.0);
  const double threads = opt.number("threads", 0);
  if (!opt.ok())
  {
    return fail(opt.error(), 2);
  }
  if (!opt.positional().empty())
  {
    return fail("unexpected argument '" + opt.positional()[0] + "' (see sltk hjb --help)", 2);
  }
  if (custom && (opt.has("preset") || opt.has("n")))
  {
    return fail("--preset and --n are for the thesis's tests; a custom problem (--fx ...) uses --nodes", 2);
  }
  if (!custom)
  {
    for (const std::string& name : hjbCustomOptionNames())
    {
      if (opt.has(name))
      {
        return fail("--" + name + " belongs to a custom problem: give its dynamics with --fx (see --help)", 2);
      }
    }
  }
  const std::string presetName = custom ? "custom" : opt.value("preset", "test1");
  int preset = custom ? vtkCWENOHJBSolver::CUSTOM : 0;
  for (int k = 1; k <= 5; ++k)
  {
    preset = presetName == "test" + std::to_string(k) ? k : preset;
  }
  if (preset == 0 && !custom)
  {
    return fail("unknown preset '" + presetName + "': use test1, test2, test3, test4 or test5", 2);
  }
  sltk::InterpolatorKind interpolator = sltk::InterpolatorKind::CwenoZ;
  if (opt.has("interpolator") && !sltk::parseInterpolator(opt.value("interpolator"), interpolator))
  {
    return fail("unknown interpolator '" + opt.value("interpolator") + "': use " + sltk::interpolatorNameList(), 2);
  }
  if (n < 5 || n > 100000 || n != static_cast<int>(n))
  {
    return fail("--n must be a whole number of nodes from 5 to 100000", 2);
  }
  if (opt.has("final-time") && finalTime < 0.0)
  {
    return fail("--final-time must be >= 0", 2);
  }
  if (opt.has("courant") && !(courant > 0.0 && courant <= 100.0))
  {
    return fail("--courant must be in (0, 100]", 2);
  }

  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkCWENOHJBSolver> solver;
  vtkNew<ErrorCollector> errors;
  solver->AddObserver(vtkCommand::ErrorEvent, errors);
  solver->SetPreset(preset);
  solver->SetNumberOfNodes(static_cast<int>(n));
  if (custom)
  {
    const std::string error = setHjbCustomProblem(opt, solver);
    if (!error.empty())
    {
      return fail(error, 2);
    }
  }
  solver->SetFinalTime(finalTime);
  solver->SetCourantNumber(courant);
  solver->SetInterpolator(static_cast<int>(interpolator));
  solver->SetNumberOfThreads(static_cast<int>(threads));
  solver->Update();
  if (!errors->Message.empty())
  {
    return fail(errors->Message);
  }
  vtkImageData* image = solver->GetOutput();
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkFieldData* fd = image->GetFieldData();
  const double t = fd->GetArray("Time")->GetTuple1(0);
  const double steps = fd->GetArray("Steps")->GetTuple1(0);
  const double evaluations = fd->GetArray("EvaluationsPerNode")->GetTuple1(0);
  const int* dims = image->GetDimensions();
  std::printf("%s, %d x %d x %d nodes, T = %g, %.0f steps, %.1f evaluations per node and step\n", presetName.c_str(),
    dims[0], dims[1], dims[2], t, steps, evaluations);
  std::printf("value in [%.6g, %.6g], %.3f s", range[0], range[1], seconds);
  const bool exact = fd->GetArray("L1Error") != nullptr;
  if (exact)
  {
    std::printf(", L1 error %.4g, Linf error %.4g", fd->GetArray("L1Error")->GetTuple1(0),
      fd->GetArray("LinfError")->GetTuple1(0));
  }
  std::printf("\n");

  if (opt.has("output"))
  {
    const auto status = writeImage(opt.value("output"), image);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (opt.has("json"))
  {
    JsonObject summary;
    summary.add("preset", presetName)
      .add("n", static_cast<long long>(dims[0]))
      .add("final_time", t)
      .add("min", range[0])
      .add("max", range[1])
      .add("seconds", seconds)
      .add("steps", static_cast<long long>(steps))
      .add("evaluations_per_node", evaluations)
      .add("peak_memory_mb", static_cast<double>(sltk::peakResidentBytes()) / 1e6);
    if (exact)
    {
      summary.add("l1_error", fd->GetArray("L1Error")->GetTuple1(0))
        .add("linf_error", fd->GetArray("LinfError")->GetTuple1(0));
    }
    auto status = writeTextFile(opt.value("json"), summary.str() + "\n");
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  return 0;
}

} // namespace sltkcli
