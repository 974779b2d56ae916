// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Context.h
/// The services injected into every long Core algorithm: executor,
/// interrupter (progress + abort) and logger. A default-constructed Context
/// runs serially, never interrupts and logs nothing.

#include "sltk/exec/Interrupter.h"
#include "sltk/exec/Logger.h"
#include "sltk/exec/ThreadPool.h"

namespace sltk
{

struct Context
{
  ThreadPool* Executor = nullptr;       ///< nullptr: run serially on the caller
  Interrupter* Progress = nullptr;      ///< nullptr: nullInterrupter()
  Logger* Log = nullptr;                ///< nullptr: nullLogger()

  Interrupter& interrupter() const { return this->Progress ? *this->Progress : nullInterrupter(); }
  Logger& logger() const { return this->Log ? *this->Log : nullLogger(); }

  /// parallelFor on the executor, or a serial loop over the same chunks.
  template <class Body>
  void parallelFor(Index begin, Index end, Body&& body, Index grain = 0) const
  {
    if (this->Executor)
    {
      this->Executor->parallelFor(begin, end, body, grain);
      return;
    }
    serialExecutor().parallelFor(begin, end, body, grain);
  }

  template <class Body>
  double parallelSum(Index begin, Index end, Body&& body, Index grain = 0) const
  {
    return (this->Executor ? *this->Executor : serialExecutor()).parallelSum(begin, end, body, grain);
  }

  /// A pool of size 1 shared by all contexts without an executor.
  static ThreadPool& serialExecutor();
};

} // namespace sltk
