// SPDX-License-Identifier: BSD-3-Clause
#include "RenderPng.h"

#include "WriteAtomically.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkVertexGlyphFilter.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>

// Last: Xlib defines macros such as Status.
#include <X11/Xlib.h>
#undef Status

namespace sltkcli
{

std::string pngProblem(const std::string& path)
{
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".png") != 0)
  {
    return "--png needs a file name ending in .png, got '" + path + "'";
  }
  const char* name = std::getenv("DISPLAY");
  Display* display = name && *name ? XOpenDisplay(name) : nullptr;
  if (!display)
  {
    return std::string("--png renders through X and cannot open the display '") + (name ? name : "") +
      "': run under a virtual one, e.g. xvfb-run -a sltk reconstruct ... --png " + path;
  }
  XCloseDisplay(display);
  return "";
}

sltk::Status renderPng(const std::string& path, vtkPolyData* surface, vtkPointSet* cloud)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkNew<vtkPolyDataNormals> normals; // smooth shading of the marching-cubes triangles
  normals->SetInputData(surface);
  normals->SetFeatureAngle(60.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.72, 0.55);
  actor->GetProperty()->SetSpecular(0.3);
  renderer->AddActor(actor);
  vtkNew<vtkVertexGlyphFilter> dots;
  vtkNew<vtkPolyDataMapper> dotMapper;
  vtkNew<vtkActor> dotActor;
  if (cloud)
  {
    dots->SetInputData(cloud);
    dotMapper->SetInputConnection(dots->GetOutputPort());
    dotMapper->ScalarVisibilityOff();
    dotActor->SetMapper(dotMapper);
    dotActor->GetProperty()->SetColor(0.1, 0.2, 0.7);
    dotActor->GetProperty()->SetPointSize(2.0);
    renderer->AddActor(dotActor);
  }
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(15.0);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(900, 700);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  return writeAtomically(path,
    [&](const std::string& temporary)
    {
      vtkNew<vtkPNGWriter> writer;
      writer->SetInputConnection(grab->GetOutputPort());
      writer->SetFileName(temporary.c_str());
      writer->Write();
      return writer->GetErrorCode() == 0;
    });
}

} // namespace sltkcli
