// SPDX-License-Identifier: BSD-3-Clause
// vtkCWENOHJBSolver with a problem given by formulas: the same values as the
// compiled preset (Test 4, (3.37)), v0 from an input image, the scheme's time
// steps advertised and served (animation), and bad formulas refused.
#include "vtkCWENOHJBSolver.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
int failures = 0;

void check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
  failures += ok ? 0 : 1;
}

/// Keeps the text of the last error event.
class ErrorText : public vtkCommand
{
public:
  static ErrorText* New() { return new ErrorText; }
  void Execute(vtkObject*, unsigned long, void* data) override { this->Text = static_cast<const char*>(data); }
  std::string Text;
};

double maxDifference(vtkDataArray* a, vtkDataArray* b)
{
  double worst = a->GetNumberOfTuples() == b->GetNumberOfTuples() ? 0.0 : INFINITY;
  for (vtkIdType k = 0; k < a->GetNumberOfTuples() && std::isfinite(worst); ++k)
  {
    worst = std::max(worst, std::fabs(a->GetTuple1(k) - b->GetTuple1(k)));
  }
  return worst;
}

/// Thesis Test 4 (3.5.4) as formulas on N x N nodes.
void setQuadraticProblem(vtkCWENOHJBSolver* s, int n)
{
  s->SetPreset(vtkCWENOHJBSolver::CUSTOM);
  s->SetDynamicsX("-a1");
  s->SetDynamicsY("-a2");
  s->SetRunningCost("(a1^2 + a2^2)/2");
  s->SetInitialValue("max(1 - (x^2 + y^2), 0)");
  s->SetExactSolution("hypot(x, y) <= 1 ? (hypot(x, y) - 1)^2 / (2*t) : 0");
  s->SetDimensions(n, n, 1);
  s->SetDomainBounds(-2, 2, -2, 2, 0, 0);
  s->SetControlSet(vtkCWENOHJBSolver::BALL);
  s->SetControlDimension(2);
  s->SetControlRadius(2.2);
  s->SetRKOrder(1);
  s->SetCourantNumber(1.25);
  s->SetFinalTime(0.5);
  s->SetTabulationPoints(33);
  s->SetMinimizerTolerance(1e-8);
  s->SetWarmStartPoints(5); // as the preset
}
} // namespace

int main()
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);

  vtkNew<vtkCWENOHJBSolver> preset;
  preset->SetPreset(vtkCWENOHJBSolver::TEST4_QUADRATIC);
  preset->SetNumberOfNodes(21);
  preset->Update();
  vtkNew<vtkCWENOHJBSolver> custom;
  setQuadraticProblem(custom, 21);
  custom->Update();
  vtkDataArray* a = preset->GetOutput()->GetPointData()->GetArray("ValueFunction");
  vtkDataArray* b = custom->GetOutput()->GetPointData()->GetArray("ValueFunction");
  check(a && b && maxDifference(a, b) < 1e-14, "custom Test 4 formulas give the preset's values");
  vtkDataArray* l1 = custom->GetOutput()->GetFieldData()->GetArray("L1Error");
  vtkDataArray* l1Preset = preset->GetOutput()->GetFieldData()->GetArray("L1Error");
  check(l1 && l1Preset && std::fabs(l1->GetTuple1(0) - l1Preset->GetTuple1(0)) < 1e-12,
    "the exact-solution formula gives the preset's L1 error");

  // Time steps: t_k = k dt with dt = 1.25 dx = 0.25, T = 0.5.
  custom->UpdateInformation();
  vtkInformation* out = custom->GetOutputInformation(0);
  const int count = out->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* times = out->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  check(count == 3 && times[0] == 0.0 && std::fabs(times[2] - 0.5) < 1e-15, "TIME_STEPS are 0, 0.25, 0.5");
  custom->UpdateTimeStep(0.3); // between steps: the last t_k <= 0.3
  vtkImageData* image = custom->GetOutput();
  check(std::fabs(image->GetFieldData()->GetArray("Time")->GetTuple1(0) - 0.25) < 1e-15 &&
      std::fabs(image->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) - 0.25) < 1e-15,
    "a request for t = 0.3 gives t_1 = 0.25");
  custom->UpdateTimeStep(0.5);
  check(maxDifference(custom->GetOutput()->GetPointData()->GetArray("ValueFunction"), a) < 1e-14,
    "continuing to t = 0.5 equals the direct solve");
  custom->UpdateTimeStep(0.0);
  check(custom->GetOutput()->GetPointData()->GetArray("ValueFunction")->GetRange()[1] == 1.0,
    "an earlier time restarts from v0 (max 1)");

  // v0 from an input image (its active scalars), on its grid.
  vtkNew<vtkImageData> field;
  field->SetDimensions(21, 21, 1);
  field->SetOrigin(-2, -2, 0);
  field->SetSpacing(0.2, 0.2, 1);
  vtkNew<vtkDoubleArray> v0;
  v0->SetName("v0");
  v0->SetNumberOfTuples(21 * 21);
  for (vtkIdType k = 0; k < 21 * 21; ++k)
  {
    double x[3];
    field->GetPoint(k, x);
    v0->SetValue(k, std::max(1.0 - (x[0] * x[0] + x[1] * x[1]), 0.0));
  }
  field->GetPointData()->SetScalars(v0);
  vtkNew<vtkCWENOHJBSolver> fromImage;
  setQuadraticProblem(fromImage, 5); // Dimensions and bounds are ignored with an input
  fromImage->SetInitialValue("");
  fromImage->SetInputData(field);
  fromImage->Update();
  vtkDataArray* c = fromImage->GetOutput()->GetPointData()->GetArray("ValueFunction");
  check(c && maxDifference(c, a) < 1e-12, "v0 from an input image gives the same solution");

  // Bad formulas: an error naming the formula and the column, no output.
  vtkNew<ErrorText> errors;
  vtkNew<vtkCWENOHJBSolver> bad;
  bad->AddObserver(vtkCommand::ErrorEvent, errors);
  setQuadraticProblem(bad, 21);
  bad->SetDynamicsY("-a2 + b");
  bad->Update();
  check(errors->Text.find("the dynamics f_D component y") != std::string::npos &&
      errors->Text.find("unknown variable 'b'") != std::string::npos &&
      errors->Text.find("column 7") != std::string::npos,
    "an unknown variable is named with its formula and column: " + errors->Text);
  errors->Text.clear();
  bad->SetDynamicsY("-a2");
  bad->SetRunningCost("(a1^2 + a2^2/2");
  bad->Update();
  check(errors->Text.find("the running cost f_C") != std::string::npos &&
      errors->Text.find("expected ')'") != std::string::npos,
    "an unbalanced parenthesis is reported: " + errors->Text);
  errors->Text.clear();
  bad->SetRunningCost("");
  bad->SetDimensions(21, 1, 21);
  bad->Update();
  check(errors->Text.find("x, then y, then z") != std::string::npos, "a grid skipping y is refused: " + errors->Text);
  return failures == 0 ? 0 : 1;
}
