// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file ErrorCollector.h
/// Keeps the last error message of a VTK algorithm (ErrorEvent) so that the
/// CLI reports it once, without VTK's file/line decoration.

#include <vtkCommand.h>

#include <string>

namespace sltkcli
{

class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    // "ERROR: In file, line N\nvtkClass (0x...): text" -> "text"
    const std::string text = static_cast<const char*>(data);
    const auto cut = text.find("): ");
    this->Message = cut == std::string::npos ? text : text.substr(cut + 3);
    while (!this->Message.empty() && (this->Message.back() == '\n' || this->Message.back() == ' '))
    {
      this->Message.pop_back();
    }
  }
  std::string Message;
};

} // namespace sltkcli
