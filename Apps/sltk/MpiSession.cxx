// SPDX-License-Identifier: BSD-3-Clause
#include "MpiSession.h"

#include <vtkCommunicator.h>
#include <vtkMPIController.h>
#include <vtkMultiProcessController.h>

#include <cstdio>
#include <cstdlib>

namespace sltkcli
{
namespace
{
bool startedByLauncher()
{
  for (const char* name : { "OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK" })
  {
    if (std::getenv(name))
    {
      return true;
    }
  }
  return false;
}
} // namespace

MpiSession::MpiSession(int* argc, char*** argv)
{
  if (!startedByLauncher())
  {
    return;
  }
  this->Controller = vtkSmartPointer<vtkMPIController>::New();
  this->Controller->Initialize(argc, argv);
  vtkMultiProcessController::SetGlobalController(this->Controller);
  if (this->Controller->GetLocalProcessId() > 0)
  {
    // Rank 0 speaks for all (MpiSession.h).
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr))
    {
      std::perror("sltk: /dev/null");
    }
  }
}

MpiSession::~MpiSession()
{
  if (this->Controller)
  {
    vtkMultiProcessController::SetGlobalController(nullptr);
    this->Controller->Finalize();
  }
}

int MpiSession::rank()
{
  auto* global = vtkMultiProcessController::GetGlobalController();
  return global ? global->GetLocalProcessId() : 0;
}

int MpiSession::size()
{
  auto* global = vtkMultiProcessController::GetGlobalController();
  return global ? global->GetNumberOfProcesses() : 1;
}

double MpiSession::maxOverRanks(double value)
{
  auto* global = vtkMultiProcessController::GetGlobalController();
  if (!global || global->GetNumberOfProcesses() < 2)
  {
    return value;
  }
  double largest = value;
  global->AllReduce(&value, &largest, 1, vtkCommunicator::MAX_OP);
  return largest;
}

} // namespace sltkcli
