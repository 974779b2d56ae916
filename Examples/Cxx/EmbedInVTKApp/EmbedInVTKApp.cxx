// SPDX-License-Identifier: BSD-3-Clause
// Using SLTK from an application: the VTK filter in a pipeline, and Core
// directly (VTK-free API) to validate a cloud before handing it over.
#include <sltk/cloud/PointCloud.h>
#include <vtkCWENOHJBSolver.h>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <iostream>

int main()
{
  vtkNew<vtkCWENOHJBSolver> solver;
  solver->SetNumberOfNodes(41);
  solver->SetFinalTime(0.0); // the initial datum of Test 1
  solver->Update();
  double range[2];
  solver->GetOutput()->GetPointData()->GetArray("ValueFunction")->GetRange(range);
  std::cout << "value function range: " << range[0] << " .. " << range[1] << "\n";

  sltk::PointCloud<3> cloud;
  cloud.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  const sltk::Status status = sltk::validateCloud(cloud);
  std::cout << "three points: " << status.toString() << "\n";

  const bool ok = range[1] > 0.14 && range[1] <= 0.15 && !status.isOk();
  std::cout << (ok ? "EmbedInVTKApp ok" : "EmbedInVTKApp FAILED") << "\n";
  return ok ? 0 : 1;
}
