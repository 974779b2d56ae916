// SPDX-License-Identifier: BSD-3-Clause
// `sltk hjb`: the HJB solver (vtkCWENOHJBSolver) from a terminal.
#include "CliOptions.h"
#include "Commands.h"
#include "ErrorCollector.h"
#include "FileNames.h"
#include "HjbCustomProblem.h"
#include "MpiSession.h"
#include "OutputPaths.h"
#include "ProgressBar.h"
#include "WriteAtomically.h"
#include "WritePieces.h"
#include "WriteSurface.h"

#include "sltk/exec/Memory.h"
#include "sltk/interp/InterpolatorKind.h"

#include <vtkCWENOHJBSolver.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

namespace sltkcli
{

namespace
{
const char* hjbDescription = R"(solve a Hamilton-Jacobi-Bellman problem (thesis ch. 3)

Solves a Hamilton-Jacobi-Bellman problem with the semi-Lagrangian scheme (3.7)
(Preda 2024, ch. 3): the thesis's Tests 1-5 with their domains, controls, RK
orders and time steps, or a problem given by formulas.

)";

/// `sltk hjb`'s command line.
struct Hjb
{
  CLI::App* Parser = nullptr;
  int Preset = 1; ///< test1..test5
  int N = 81;
  double FinalTime = -1.0; // the preset's
  double Courant = 0.0;    // the preset's
  sltk::InterpolatorKind Interpolator = sltk::InterpolatorKind::CwenoZ;
  int Threads = 0;
  bool Quiet = false;
  std::string Output, Json;
  HjbCustomProblem Custom;
  int run() const;
};

int Hjb::run() const
{
  const bool custom = this->Parser->count("--fx") || this->Parser->count("--fy") || this->Parser->count("--fz");
  if (custom && (this->Parser->count("--preset") || this->Parser->count("--n")))
  {
    return fail("--preset and --n are for the thesis's tests; a custom problem (--fx ...) uses --nodes", 2);
  }
  for (const CLI::Option* option : this->Parser->get_options())
  {
    if (!custom && option->count() && option->get_group() == HjbCustomProblem::Group)
    {
      return fail(option->get_name() + " belongs to a custom problem: give its dynamics with --fx (see --help)", 2);
    }
  }
  const std::string paths =
    outputPathsProblem({}, { { "-o", this->Output, { "vti", "pvti" } }, { "--json", this->Json, { "json" } } });
  if (!paths.empty())
  {
    return fail(paths, 2);
  }
  const bool pieces = extensionOf(this->Output) == "pvti";
  const std::string folder = pieces ? pieceFolderProblem(this->Output) : "";
  if (!folder.empty())
  {
    return fail(folder, 2);
  }
  const std::string presetName = custom ? "custom" : "test" + std::to_string(this->Preset);
  const int preset = custom ? vtkCWENOHJBSolver::CUSTOM : this->Preset;
  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkCWENOHJBSolver> solver;
  vtkNew<ErrorCollector> errors;
  solver->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<ProgressBar> bar; // a long solve is not silent for minutes (on a terminal)
  if (!this->Quiet)
  {
    solver->AddObserver(vtkCommand::ProgressEvent, bar);
  }
  solver->SetPreset(preset);
  solver->SetNumberOfNodes(this->N);
  if (custom)
  {
    const std::string error = this->Custom.apply(solver);
    if (!error.empty())
    {
      return fail(error, 2);
    }
  }
  solver->SetFinalTime(this->FinalTime);
  solver->SetCourantNumber(this->Courant);
  solver->SetInterpolator(static_cast<int>(this->Interpolator));
  solver->SetNumberOfThreads(this->Threads); // the filter shares the cores among the ranks
  // Each rank computes its block of the grid; rank 0 also collects the whole image when it writes one .vti.
  const int rank = MpiSession::rank(), ranks = MpiSession::size();
  if (ranks > 1 && (pieces || rank > 0))
  {
    solver->UpdatePiece(rank, ranks, 0);
  }
  else
  {
    solver->Update();
  }
  bar->finish();
  if (!errors->Message.empty())
  {
    return fail(errors->Message);
  }
  vtkImageData* image = solver->GetOutput();
  double range[2];
  image->GetPointData()->GetScalars()->GetRange(range);
  range[0] = -MpiSession::maxOverRanks(-range[0]);
  range[1] = MpiSession::maxOverRanks(range[1]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkFieldData* fd = image->GetFieldData();
  const double t = fd->GetArray("Time")->GetTuple1(0);
  const double steps = fd->GetArray("Steps")->GetTuple1(0);
  const double evaluations = fd->GetArray("EvaluationsPerNode")->GetTuple1(0);
  int extent[6];
  solver->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  const int dims[3] = { extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1 };
  std::printf("%s, %d x %d x %d nodes, T = %g, %.0f steps, %.1f evaluations per node and step", presetName.c_str(),
    dims[0], dims[1], dims[2], t, steps, evaluations);
  std::printf(ranks > 1 ? ", %d ranks\n" : "\n", ranks);
  std::printf("value in [%.6g, %.6g], %.3f s", range[0], range[1], seconds);
  const bool exact = fd->GetArray("L1Error") != nullptr;
  if (exact)
  {
    std::printf(", L1 error %.4g, Linf error %.4g", fd->GetArray("L1Error")->GetTuple1(0),
      fd->GetArray("LinfError")->GetTuple1(0));
  }
  std::printf("\n");

  if (pieces)
  {
    const auto status = writeImagePieces(this->Output, solver, vtkMultiProcessController::GetGlobalController());
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  const double peakMb = MpiSession::maxOverRanks(static_cast<double>(sltk::peakResidentBytes()) / 1e6);
  if (rank > 0)
  {
    return 0; // rank 0 writes the one set of outputs
  }
  if (this->Parser->count("--output") && !pieces)
  {
    const auto status = writeImage(this->Output, image);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  if (this->Parser->count("--json"))
  {
    nlohmann::ordered_json summary = { { "preset", presetName }, { "n", dims[0] }, { "final_time", t },
      { "min", range[0] }, { "max", range[1] }, { "seconds", seconds }, { "steps", static_cast<long long>(steps) },
      { "evaluations_per_node", evaluations }, { "peak_memory_mb", peakMb }, { "ranks", ranks } };
    if (exact)
    {
      summary["l1_error"] = fd->GetArray("L1Error")->GetTuple1(0);
      summary["linf_error"] = fd->GetArray("LinfError")->GetTuple1(0);
    }
    auto status = writeJsonFile(this->Json, summary);
    if (!status.isOk())
    {
      return fail(status.message());
    }
  }
  return 0;
}
} // namespace

Command addHjbCommand(CLI::App& sltk)
{
  auto command = std::make_shared<Hjb>();
  CLI::App* app = sltk.add_subcommand("hjb", std::string(hjbDescription) + HjbCustomProblem::Help);
  command->Parser = app;
  app->footer("example (thesis Test 4): sltk hjb --fx=-a1 --fy=-a2 --cost \"(a1^2+a2^2)/2\"\n"
              "  --v0 \"max(1-x^2-y^2,0)\" --nodes 81,81 --domain -2,2,-2,2 --controls ball\n"
              "  --control-dim 2 --control-radius 2.2 --rk 1 --courant 1.25 --final-time 0.5");
  addChoice(
    app, "--preset", "preset", { "test1", "test2", "test3", "test4", "test5" },
    [&preset = command->Preset](size_t k) { preset = static_cast<int>(k) + 1; },
    "test1 (rotation, 2D) | test2 (semi-concave, 1D) | test3 (eikonal,\n1D periodic) | test4 (quadratic, 2D) "
    "| test5 (Zermelo with\nobstacles, 2D)   (default test1)")
    ->option_text("NAME");
  addNumber(app, "--n", command->N, "preset: nodes per direction, 5 to 100000 (default 81)")
    ->check(withinRange("NumberOfNodes"))
    ->option_text("N");
  addNumber(app, "--final-time", command->FinalTime, "final time (default: the preset's; 0 gives the initial datum)")
    ->check(within(0))
    ->option_text("T");
  addNumber(app, "--courant", command->Courant,
    "dt = L dx, L in [0, 100] (default 0: the preset's; custom: 1,\ndx the smallest spacing)")
    ->check(withinRange("CourantNumber"))
    ->option_text("L");
  addInterpolatorOption(app, command->Interpolator, "cwenoz");
  addThreadsOption(app, command->Threads);
  app->add_flag("--quiet", command->Quiet, "no progress bar");
  app
    ->add_option("-o,--output", command->Output,
      "write the value function (and ReachTime for test5); under mpirun,\n.pvti: every rank writes its own block "
      "(FILE/FILE_<rank>.vti)")
    ->option_text("FILE.vti|.pvti");
  app
    ->add_option("--json", command->Json,
      "summary: l1_error, linf_error (when exact), min, max, seconds, steps,\nevaluations_per_node, peak_memory_mb "
      "(the largest rank's), ranks")
    ->option_text("FILE");
  command->Custom.addOptions(app);
  return { app, [command] { return command->run(); } };
}

} // namespace sltkcli
