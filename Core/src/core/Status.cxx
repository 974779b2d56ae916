// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/core/Status.h"

namespace sltk
{

const char* toString(StatusCode code)
{
  switch (code)
  {
    case StatusCode::Ok:
      return "ok";
    case StatusCode::InvalidArgument:
      return "invalid argument";
    case StatusCode::OutOfMemory:
      return "out of memory";
    case StatusCode::Aborted:
      return "aborted";
    case StatusCode::NumericalFailure:
      return "numerical failure";
    case StatusCode::NotImplemented:
      return "not implemented";
    case StatusCode::IOError:
      return "I/O error";
  }
  return "unknown";
}

std::string Status::toString() const
{
  if (this->isOk())
  {
    return "ok";
  }
  return std::string(sltk::toString(this->Code)) + ": " + this->Message;
}

} // namespace sltk
