// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Status.h
/// Result of a Core operation. Core never throws across its boundary: every
/// fallible entry point returns a Status that the VTK filter turns into
/// vtkErrorMacro + `return 0`, and the CLI into a message and an exit code.

#include <string>
#include <utility>

namespace sltk
{

enum class StatusCode
{
  Ok = 0,
  InvalidArgument,   ///< bad parameter or input data (message names it and the fix)
  OutOfMemory,       ///< the request would exceed available memory
  Aborted,           ///< the interrupter asked to stop
  NumericalFailure,  ///< NaN/Inf produced or a scheme failed to converge
  NotImplemented,    ///< the feature is not available (yet) in this build
  IOError            ///< a file could not be read or written
};

/// Short lower-case name of a code, e.g. "invalid argument".
const char* toString(StatusCode code);

class Status
{
public:
  Status() = default;
  Status(StatusCode code, std::string message)
    : Code(code)
    , Message(std::move(message))
  {
  }

  static Status ok() { return {}; }
  static Status invalidArgument(std::string m) { return { StatusCode::InvalidArgument, std::move(m) }; }
  static Status outOfMemory(std::string m) { return { StatusCode::OutOfMemory, std::move(m) }; }
  static Status aborted(std::string m = "aborted by the user") { return { StatusCode::Aborted, std::move(m) }; }
  static Status numericalFailure(std::string m) { return { StatusCode::NumericalFailure, std::move(m) }; }
  static Status notImplemented(std::string m) { return { StatusCode::NotImplemented, std::move(m) }; }
  static Status ioError(std::string m) { return { StatusCode::IOError, std::move(m) }; }

  bool isOk() const { return this->Code == StatusCode::Ok; }
  explicit operator bool() const { return this->isOk(); }
  StatusCode code() const { return this->Code; }
  const std::string& message() const { return this->Message; }
  /// "invalid argument: <message>", or "ok".
  std::string toString() const;

private:
  StatusCode Code = StatusCode::Ok;
  std::string Message;
};

} // namespace sltk

/// Return early from the enclosing function when `expr` yields a failed Status.
#define SLTK_RETURN_IF_ERROR(expr)                                                                 \
  do                                                                                               \
  {                                                                                                \
    ::sltk::Status sltkStatus_ = (expr);                                                           \
    if (!sltkStatus_.isOk())                                                                       \
      return sltkStatus_;                                                                          \
  } while (0)
