// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// \file Expression.h
/// A user formula such as "2 - y^2/2 + a1" compiled once into a short postfix
/// program and evaluated many times (the HJB problem's f_D, f_C, v_0, g of
/// (3.1)-(3.4), (3.39)). Evaluation is const, allocation-free and thread-safe:
/// every thread may evaluate the same Expression with its own values.
///
/// Syntax (C-like precedence, lowest first):
///   c ? a : b      conditional          a || b, a && b, !a    logic (non-zero is true, results 0/1)
///   < <= > >= == !=                     comparisons (0/1)
///   + -            * / %                arithmetic (% is fmod)
///   -a, +a         unary                a ^ b, a ** b  power (right-associative, binds tighter than unary minus: -x^2
///   = -(x^2)) numbers 1, 2.5, 1e-3, constants pi and e, the caller's variables, and functions sin cos tan asin acos
///   atan sinh cosh tanh exp log log10 log2 sqrt cbrt abs floor ceil round sign atan2(y, x) pow(a, b) hypot(a, b)
///   fmod(a, b) min(a, b, ...) max(a, b, ...) clamp(v, lo, hi) if(c, a, b)
/// Sub-expressions without variables are folded to constants when compiled.
///
/// Why not ExprTk (vtk_exprtk.h): Core stays VTK-free (Documentation/Architecture.md), the
/// messages here name the expression and the column of the mistake, and a
/// compiled program needs no per-thread copy of a symbol table.

#include "sltk/core/Status.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sltk
{

class Expression
{
public:
  /// Compiles `text`. `variables` are the names evaluate() reads, in order;
  /// `what` names the expression in messages (e.g. "the dynamics f_D[2]").
  /// An error names `what`, the column and the problem, and lists the variables.
  static Status compile(const std::string& what,
    const std::string& text,
    const std::vector<std::string>& variables,
    Expression& out);

  /// The value for values[k] = variable k. Non-finite results are returned as they are.
  double evaluate(const double* values) const;

  bool isCompiled() const { return !this->Code.empty(); }
  /// True when the expression reads no variable (then evaluate(nullptr) is allowed).
  bool isConstant() const { return this->Code.size() == 1 && this->Code[0].Code == Op::Constant; }
  /// True when variable k occurs in the expression.
  bool uses(int variable) const;
  const std::string& text() const { return this->Text; }
  /// The name given to compile(), e.g. "the running cost f_C".
  const std::string& what() const { return this->What; }

  /// Deepest evaluation stack a program may need (deeper nesting is refused).
  static constexpr int MaxStackDepth = 64;

  enum class Op : std::uint8_t
  {
    Constant,
    Variable,
    Negate,
    Not,
    Add,
    Subtract,
    Multiply,
    Divide,
    Modulo,
    Power,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    Equal,
    NotEqual,
    And,
    Or,
    Select,    ///< c ? a : b
    Function1, ///< Function: index into the unary function table
    Function2  ///< Function: index into the binary function table
  };
  struct Instruction
  {
    Op Code = Op::Constant;
    std::uint8_t Function = 0;
    std::int32_t Variable = 0;
    double Value = 0.0;
  };

private:
  friend class ExpressionCompiler;
  std::string Text;
  std::string What;
  std::vector<Instruction> Code;
};

} // namespace sltk
