// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: Expression::compile() on any text (an HJB formula as a
// user types it), then evaluate() at a few points when it compiles. A crash,
// a sanitizer report or an unbounded stack is a bug; an error Status is not.
#include "sltk/expr/Expression.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  static const std::vector<std::string> variables{ "x", "y", "z", "t", "a1", "a2", "a3" };
  sltk::Expression e;
  if (!sltk::Expression::compile("the fuzzed formula", text, variables, e).isOk())
  {
    return 0;
  }
  const double points[3][7] = { { 0, 0, 0, 0, 0, 0, 0 }, { -1, 0.5, 2, 1e-3, 1, -1, 0 },
    { 1e300, -1e-300, 3.5, 7, -2, 2, 1e10 } };
  volatile double sink = 0.0;
  for (const auto& p : points)
  {
    sink = sink + e.evaluate(p);
  }
  (void)sink;
  return 0;
}
