// SPDX-License-Identifier: BSD-3-Clause
// `sltk hjb`: the HJB solver (vtkCWENOHJBSolver) from a terminal.
#include "Commands.h"
#include "ErrorCollector.h"
#include "Json.h"
#include "WriteAtomically.h"

#include "sltk/exec/Memory.h"

#include <vtkCWENOHJBSolver.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <chrono>
#include <iostream>

namespace sltkcli
{

namespace
{
const char* hjbUsage = R"(usage: sltk hjb [options]

Solves a Hamilton-Jacobi-Bellman problem with the semi-Lagrangian scheme (3.7).
This version evaluates the initial datum (--final-time 0); time stepping is not
built yet and a positive final time is reported as an error.

options:
  --preset NAME          test1 (rotation of a C2 bump, 3.5.1) (default test1)
  --n N                  nodes per direction, both ends included (default 81)
  --final-time T         final time (default 0)
  --interpolator NAME    q1 | weno3 | cweno | cwenoz (default cwenoz)
  --threads T            threads (default: all)
  -o, --output FILE.vti  write the value function
  --json FILE            write a summary (min, max, seconds, ...)
)";

int interpolatorCode(const std::string& name)
{
  if (name == "q1")
    return vtkCWENOHJBSolver::Q1;
  if (name == "weno3")
    return vtkCWENOHJBSolver::WENO3;
  if (name == "cweno")
    return vtkCWENOHJBSolver::CWENO;
  if (name == "cwenoz")
    return vtkCWENOHJBSolver::CWENOZ;
  return -1;
}

} // namespace

int commandHjb(const Args& rawArgs)
{
  Args args = rawArgs;
  for (auto& a : args)
  {
    a = a == "-o" ? "--output" : a;
  }
  Options opt(args, { "preset", "n", "final-time", "interpolator", "threads", "output", "json" }, { "help" });
  if (opt.has("help"))
  {
    std::cout << hjbUsage;
    return 0;
  }
  const double n = opt.number("n", 81);
  const double finalTime = opt.number("final-time", 0.0);
  const double threads = opt.number("threads", 0);
  if (!opt.ok())
  {
    return fail(opt.error(), 2);
  }
  if (!opt.positional().empty())
  {
    return fail("unexpected argument '" + opt.positional()[0] + "' (see sltk hjb --help)", 2);
  }
  if (opt.value("preset", "test1") != "test1")
  {
    return fail("unknown preset '" + opt.value("preset") + "': available: test1", 2);
  }
  const int interpolator = interpolatorCode(opt.value("interpolator", "cwenoz"));
  if (interpolator < 0)
  {
    return fail("unknown interpolator '" + opt.value("interpolator") + "': use q1, weno3, cweno or cwenoz", 2);
  }
  if (n < 3 || n > 100000 || n != static_cast<int>(n))
  {
    return fail("--n must be a whole number of nodes from 3 to 100000", 2);
  }
  if (finalTime < 0.0)
  {
    return fail("--final-time must be >= 0", 2);
  }

  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkCWENOHJBSolver> solver;
  vtkNew<ErrorCollector> errors;
  solver->AddObserver(vtkCommand::ErrorEvent, errors);
  solver->SetDimensions(static_cast<int>(n), static_cast<int>(n), 1);
  solver->SetFinalTime(finalTime);
  solver->SetInterpolator(interpolator);
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
  std::printf("preset test1, %d x %d nodes, T = %g: value in [%.6g, %.6g], %.3f s\n", static_cast<int>(n),
    static_cast<int>(n), finalTime, range[0], range[1], seconds);

  if (opt.has("output"))
  {
    const std::string path = opt.value("output");
    auto status = writeAtomically(path, [&](const std::string& temporary) {
      vtkNew<vtkXMLImageDataWriter> writer;
      writer->SetInputData(image);
      writer->SetFileName(temporary.c_str());
      return writer->Write() == 1;
    });
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (opt.has("json"))
  {
    JsonObject summary;
    summary.add("preset", std::string("test1"))
      .add("n", static_cast<long long>(n))
      .add("final_time", finalTime)
      .add("min", range[0])
      .add("max", range[1])
      .add("seconds", seconds)
      .add("steps", 0LL)
      .add("peak_memory_mb", static_cast<double>(sltk::peakResidentBytes()) / 1e6);
    auto status = writeTextFile(opt.value("json"), summary.str() + "\n");
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  return 0;
}

} // namespace sltkcli
