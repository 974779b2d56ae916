// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ProgressBar.h
/// A terminal progress bar fed by a VTK algorithm's ProgressEvent (stderr,
/// only when it is a terminal).

#include <vtkAlgorithm.h>
#include <vtkCommand.h>

#include <cstdio>
#include <string>
#include <unistd.h>

namespace sltkcli
{

class ProgressBar : public vtkCommand
{
public:
  static ProgressBar* New() { return new ProgressBar; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    if (!this->Terminal)
    {
      return;
    }
    const double fraction = *static_cast<double*>(data);
    auto* algorithm = vtkAlgorithm::SafeDownCast(caller);
    const char* text = algorithm && algorithm->GetProgressText() ? algorithm->GetProgressText() : "";
    const int width = 40;
    const int filled = static_cast<int>(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%% %-12s", std::string(static_cast<size_t>(filled), '#').c_str(),
      std::string(static_cast<size_t>(width - filled), ' ').c_str(), static_cast<int>(100 * fraction + 0.5), text);
    std::fflush(stderr);
    this->Drawn = true;
  }
  /// Ends the bar's line.
  void finish()
  {
    if (this->Drawn)
    {
      std::fprintf(stderr, "\n");
      this->Drawn = false;
    }
  }

private:
  bool Terminal = ::isatty(2) != 0;
  bool Drawn = false;
};

} // namespace sltkcli
