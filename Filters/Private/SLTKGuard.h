// SPDX-License-Identifier: BSD-3-Clause
#ifndef SLTKGuard_h
#define SLTKGuard_h
/// \file SLTKGuard.h
/// No exception crosses a filter's pipeline request (Documentation/Architecture.md,
/// "Errors, logging, interrupts"): the memory checks size what they can before
/// allocating, and what they could not foresee (std::bad_alloc) or any other
/// exception becomes the filter's error, so ParaView and pvpython keep running.

#include "vtkAlgorithm.h"
#include "vtkSetGet.h"

#include <exception>
#include <new>

namespace sltk
{
namespace vtkbridge
{

template <class Request>
int guardedRequest(vtkAlgorithm* self, Request&& request)
{
  try
  {
    return request();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(self,
      "out of memory: the request needs more memory than this machine can give; "
      "use a coarser grid (fewer nodes) or fewer runs");
  }
  catch (const std::exception& e)
  {
    vtkErrorWithObjectMacro(self, "internal error: " << e.what());
  }
  return 0;
}

} // namespace vtkbridge
} // namespace sltk

#endif
