// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Interrupter.h
/// Progress reporting and cancellation, injected into long Core algorithms
/// (the OpenVDB "interrupter" shape). The VTK filters map it onto
/// UpdateProgress + CheckAbort, the CLI onto a progress bar.
///
/// Contract: Core calls these methods from the thread that called the
/// algorithm only (never from worker threads), between parallel sections.

#include <string>

namespace sltk
{

class Interrupter
{
public:
  virtual ~Interrupter() = default;
  /// A named phase begins (e.g. "run 2/3").
  virtual void start(const std::string& /*phase*/) {}
  /// The current phase ended.
  virtual void end() {}
  /// Report progress in [0, 1] (negative: unknown) and ask whether to stop.
  virtual bool wasInterrupted(double /*fraction*/ = -1.0) { return false; }
};

/// The interrupter used when the caller injects none: never interrupts.
Interrupter& nullInterrupter();

} // namespace sltk
