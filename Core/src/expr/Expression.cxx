// SPDX-License-Identifier: BSD-3-Clause
#include "sltk/expr/Expression.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace sltk
{

namespace
{
using Op = Expression::Op;
using Instruction = Expression::Instruction;

struct UnaryFunction
{
  const char* Name;
  double (*Apply)(double);
};
struct BinaryFunction
{
  const char* Name;
  double (*Apply)(double, double);
};

const UnaryFunction unaryFunctions[] = {
  { "sin", [](double v) { return std::sin(v); } },
  { "cos", [](double v) { return std::cos(v); } },
  { "tan", [](double v) { return std::tan(v); } },
  { "asin", [](double v) { return std::asin(v); } },
  { "acos", [](double v) { return std::acos(v); } },
  { "atan", [](double v) { return std::atan(v); } },
  { "sinh", [](double v) { return std::sinh(v); } },
  { "cosh", [](double v) { return std::cosh(v); } },
  { "tanh", [](double v) { return std::tanh(v); } },
  { "exp", [](double v) { return std::exp(v); } },
  { "log", [](double v) { return std::log(v); } },
  { "log10", [](double v) { return std::log10(v); } },
  { "log2", [](double v) { return std::log2(v); } },
  { "sqrt", [](double v) { return std::sqrt(v); } },
  { "cbrt", [](double v) { return std::cbrt(v); } },
  { "abs", [](double v) { return std::fabs(v); } },
  { "floor", [](double v) { return std::floor(v); } },
  { "ceil", [](double v) { return std::ceil(v); } },
  { "round", [](double v) { return std::round(v); } },
  { "sign", [](double v) { return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0); } },
};

// min and max come first: min(a, b, ...) and max(a, b, ...) chain them.
const BinaryFunction binaryFunctions[] = {
  { "min", [](double a, double b) { return a < b ? a : b; } },
  { "max", [](double a, double b) { return a > b ? a : b; } },
  { "atan2", [](double a, double b) { return std::atan2(a, b); } },
  { "pow", [](double a, double b) { return std::pow(a, b); } },
  { "hypot", [](double a, double b) { return std::hypot(a, b); } },
  { "fmod", [](double a, double b) { return std::fmod(a, b); } },
};
constexpr std::uint8_t MinIndex = 0;
constexpr std::uint8_t MaxIndex = 1;

/// Stack effect of an instruction: values popped minus values pushed is 1 - pushes.
int popped(Op op)
{
  switch (op)
  {
    case Op::Constant:
    case Op::Variable:
      return 0;
    case Op::Negate:
    case Op::Not:
    case Op::Function1:
      return 1;
    case Op::Select:
      return 3;
    default:
      return 2;
  }
}

/// Runs `code` on a fixed stack; the program is known to be well formed.
double run(const Instruction* code, size_t size, const double* values)
{
  double s[Expression::MaxStackDepth];
  int top = -1;
  for (size_t k = 0; k < size; ++k)
  {
    const Instruction& in = code[k];
    switch (in.Code)
    {
      case Op::Constant:
        s[++top] = in.Value;
        break;
      case Op::Variable:
        s[++top] = values[in.Variable];
        break;
      case Op::Negate:
        s[top] = -s[top];
        break;
      case Op::Not:
        s[top] = s[top] == 0.0 ? 1.0 : 0.0;
        break;
      case Op::Function1:
        s[top] = unaryFunctions[in.Function].Apply(s[top]);
        break;
      case Op::Select:
        top -= 2;
        s[top] = s[top] != 0.0 ? s[top + 1] : s[top + 2];
        break;
      default:
      {
        const double b = s[top--];
        double& a = s[top];
        switch (in.Code)
        {
          case Op::Add:
            a += b;
            break;
          case Op::Subtract:
            a -= b;
            break;
          case Op::Multiply:
            a *= b;
            break;
          case Op::Divide:
            a /= b;
            break;
          case Op::Modulo:
            a = std::fmod(a, b);
            break;
          case Op::Power:
            a = b == 2.0 ? a * a : std::pow(a, b);
            break;
          case Op::Less:
            a = a < b ? 1.0 : 0.0;
            break;
          case Op::LessEqual:
            a = a <= b ? 1.0 : 0.0;
            break;
          case Op::Greater:
            a = a > b ? 1.0 : 0.0;
            break;
          case Op::GreaterEqual:
            a = a >= b ? 1.0 : 0.0;
            break;
          case Op::Equal:
            a = a == b ? 1.0 : 0.0;
            break;
          case Op::NotEqual:
            a = a != b ? 1.0 : 0.0;
            break;
          case Op::And:
            a = (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
            break;
          case Op::Or:
            a = (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
            break;
          case Op::Function2:
            a = binaryFunctions[in.Function].Apply(a, b);
            break;
          default:
            break;
        }
      }
    }
  }
  return s[0];
}

struct SyntaxError
{
  size_t Column; // 0-based position in the text
  std::string Problem;
};

} // namespace

/// Recursive-descent parser emitting postfix code, with constant folding.
class ExpressionCompiler
{
public:
  ExpressionCompiler(const std::string& text, const std::vector<std::string>& variables)
    : Text(text)
    , Variables(variables)
  {
  }

  std::vector<Instruction> compile()
  {
    this->skipSpace();
    if (this->Pos == this->Text.size())
    {
      throw SyntaxError{ 0, "is empty" };
    }
    this->conditional();
    this->skipSpace();
    if (this->Pos != this->Text.size())
    {
      throw SyntaxError{ this->Pos, "unexpected '" + std::string(1, this->Text[this->Pos]) + "'" };
    }
    return std::move(this->Code);
  }

private:
  const std::string& Text;
  const std::vector<std::string>& Variables;
  size_t Pos = 0;
  std::vector<Instruction> Code;

  void skipSpace()
  {
    while (this->Pos < this->Text.size() && std::isspace(static_cast<unsigned char>(this->Text[this->Pos])))
    {
      ++this->Pos;
    }
  }
  /// Consumes `token` (after spaces) when it comes next.
  bool accept(const char* token)
  {
    this->skipSpace();
    const size_t n = std::strlen(token);
    if (this->Text.compare(this->Pos, n, token) == 0)
    {
      this->Pos += n;
      return true;
    }
    return false;
  }
  void expect(const char* token, const char* context)
  {
    if (!this->accept(token))
    {
      throw SyntaxError{ this->Pos,
        std::string("expected '") + token + "' " + context +
          (this->Pos < this->Text.size() ? ", found '" + std::string(1, this->Text[this->Pos]) + "'"
                                         : ", found the end") };
    }
  }

  void emit(Op op, std::uint8_t function = 0)
  {
    Instruction in;
    in.Code = op;
    in.Function = function;
    const int arity = popped(op);
    const size_t n = this->Code.size();
    bool constant = n >= static_cast<size_t>(arity);
    for (int k = 1; k <= arity && constant; ++k)
    {
      constant = this->Code[n - static_cast<size_t>(k)].Code == Op::Constant;
    }
    if (constant && arity > 0)
    {
      // A postfix run ending in `arity` constants is exactly the operands: fold.
      this->Code.push_back(in);
      const double value =
        run(this->Code.data() + (n - static_cast<size_t>(arity)), static_cast<size_t>(arity) + 1, nullptr);
      this->Code.resize(n - static_cast<size_t>(arity));
      this->constant(value);
      return;
    }
    this->Code.push_back(in);
  }
  void constant(double value)
  {
    Instruction in;
    in.Code = Op::Constant;
    in.Value = value;
    this->Code.push_back(in);
  }

  void conditional()
  {
    this->logicalOr();
    if (this->accept("?"))
    {
      this->conditional();
      this->expect(":", "in 'c ? a : b'");
      this->conditional();
      this->emit(Op::Select);
    }
  }
  void logicalOr()
  {
    this->logicalAnd();
    while (this->accept("||"))
    {
      this->logicalAnd();
      this->emit(Op::Or);
    }
  }
  void logicalAnd()
  {
    this->comparison();
    while (this->accept("&&"))
    {
      this->comparison();
      this->emit(Op::And);
    }
  }
  void comparison()
  {
    this->additive();
    static const std::pair<const char*, Op> ops[] = { { "<=", Op::LessEqual },
      { ">=", Op::GreaterEqual },
      { "==", Op::Equal },
      { "!=", Op::NotEqual },
      { "<", Op::Less },
      { ">", Op::Greater } };
    for (const auto& [token, op] : ops)
    {
      if (this->accept(token))
      {
        this->additive();
        this->emit(op);
        return;
      }
    }
  }
  void additive()
  {
    this->multiplicative();
    for (;;)
    {
      if (this->accept("+"))
      {
        this->multiplicative();
        this->emit(Op::Add);
      }
      else if (this->accept("-"))
      {
        this->multiplicative();
        this->emit(Op::Subtract);
      }
      else
      {
        return;
      }
    }
  }
  void multiplicative()
  {
    this->unary();
    for (;;)
    {
      if (this->accept("*"))
      {
        this->unary();
        this->emit(Op::Multiply);
      }
      else if (this->accept("/"))
      {
        this->unary();
        this->emit(Op::Divide);
      }
      else if (this->accept("%"))
      {
        this->unary();
        this->emit(Op::Modulo);
      }
      else
      {
        return;
      }
    }
  }
  void unary()
  {
    if (this->accept("-"))
    {
      this->unary();
      this->emit(Op::Negate);
    }
    else if (this->accept("+"))
    {
      this->unary();
    }
    else if (this->accept("!"))
    {
      this->unary();
      this->emit(Op::Not);
    }
    else
    {
      this->power();
    }
  }
  void power()
  {
    this->primary();
    if (this->accept("^") || this->accept("**"))
    {
      this->unary(); // right-associative; 2^-1 allowed
      this->emit(Op::Power);
    }
  }
  void primary()
  {
    this->skipSpace();
    if (this->Pos == this->Text.size())
    {
      throw SyntaxError{ this->Pos, "ends where a value is expected" };
    }
    const char c = this->Text[this->Pos];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.')
    {
      this->number();
      return;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_')
    {
      this->name();
      return;
    }
    if (this->accept("("))
    {
      this->conditional();
      this->expect(")", "to close '('");
      return;
    }
    throw SyntaxError{ this->Pos, "unexpected '" + std::string(1, c) + "' where a value is expected" };
  }
  void number()
  {
    const char* begin = this->Text.data() + this->Pos;
    const char* end = this->Text.data() + this->Text.size();
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr == begin)
    {
      throw SyntaxError{ this->Pos, "malformed number" };
    }
    this->Pos += static_cast<size_t>(ptr - begin);
    if (this->Pos < this->Text.size() &&
      (std::isalpha(static_cast<unsigned char>(this->Text[this->Pos])) || this->Text[this->Pos] == '_'))
    {
      throw SyntaxError{ this->Pos, "a number followed by a name: write '*' for a product" };
    }
    this->constant(value);
  }
  void name()
  {
    const size_t start = this->Pos;
    while (this->Pos < this->Text.size() &&
      (std::isalnum(static_cast<unsigned char>(this->Text[this->Pos])) || this->Text[this->Pos] == '_'))
    {
      ++this->Pos;
    }
    const std::string id = this->Text.substr(start, this->Pos - start);
    this->skipSpace();
    if (this->Pos < this->Text.size() && this->Text[this->Pos] == '(')
    {
      ++this->Pos;
      this->call(id, start);
      return;
    }
    for (size_t k = 0; k < this->Variables.size(); ++k)
    {
      if (this->Variables[k] == id)
      {
        Instruction in;
        in.Code = Op::Variable;
        in.Variable = static_cast<std::int32_t>(k);
        this->Code.push_back(in);
        return;
      }
    }
    if (id == "pi")
    {
      this->constant(3.14159265358979323846);
      return;
    }
    if (id == "e")
    {
      this->constant(2.71828182845904523536);
      return;
    }
    throw SyntaxError{ start, "unknown variable '" + id + "'" };
  }
  /// Arguments after '(' up to ')'; returns their number. With `chain` >= 0
  /// (min, max of any arity) emits that binary function after each argument
  /// from the second on: min(a, b, c) -> a b min c min.
  int arguments(const std::string& id, int chain = -1)
  {
    if (this->accept(")"))
    {
      return 0;
    }
    int count = 0;
    do
    {
      this->conditional();
      if (++count >= 2 && chain >= 0)
      {
        this->emit(Op::Function2, static_cast<std::uint8_t>(chain));
      }
    } while (this->accept(","));
    this->expect(")", ("to close the arguments of " + id + "()").c_str());
    return count;
  }
  void call(const std::string& id, size_t start)
  {
    auto arity = [&](int got, int want)
    {
      if (got != want)
      {
        throw SyntaxError{ start,
          id + "() takes " + std::to_string(want) + " argument" + (want > 1 ? "s" : "") + ", got " +
            std::to_string(got) };
      }
    };
    if (id == "if")
    {
      arity(this->arguments(id), 3);
      this->emit(Op::Select);
      return;
    }
    if (id == "clamp")
    {
      // clamp(v, lo, hi) = min(max(v, lo), hi): the arguments come in emission order.
      this->conditional();
      this->expect(",", "after the value of clamp(v, lo, hi)");
      this->conditional();
      this->emit(Op::Function2, MaxIndex);
      this->expect(",", "after the lower bound of clamp(v, lo, hi)");
      this->conditional();
      this->emit(Op::Function2, MinIndex);
      this->expect(")", "to close clamp(v, lo, hi)");
      return;
    }
    for (size_t k = 0; k < sizeof(unaryFunctions) / sizeof(unaryFunctions[0]); ++k)
    {
      if (id == unaryFunctions[k].Name)
      {
        arity(this->arguments(id), 1);
        this->emit(Op::Function1, static_cast<std::uint8_t>(k));
        return;
      }
    }
    for (size_t k = 0; k < sizeof(binaryFunctions) / sizeof(binaryFunctions[0]); ++k)
    {
      if (id == binaryFunctions[k].Name)
      {
        const bool variadic = k == MinIndex || k == MaxIndex;
        if (!variadic)
        {
          arity(this->arguments(id), 2);
          this->emit(Op::Function2, static_cast<std::uint8_t>(k));
          return;
        }
        const int got = this->arguments(id, static_cast<int>(k));
        if (got < 2)
        {
          throw SyntaxError{ start, id + "() takes at least 2 arguments, got " + std::to_string(got) };
        }
        return;
      }
    }
    throw SyntaxError{ start, "unknown function '" + id + "'" };
  }
};

Status Expression::compile(const std::string& what,
  const std::string& text,
  const std::vector<std::string>& variables,
  Expression& out)
{
  out = Expression{};
  auto failure = [&](size_t column, const std::string& problem)
  {
    std::string names;
    for (const std::string& v : variables)
    {
      if (!v.empty())
      {
        names += (names.empty() ? "" : ", ") + v;
      }
    }
    return Status::invalidArgument(what + " \"" + text + "\": " + problem + " at column " + std::to_string(column + 1) +
      " (variables: " + (names.empty() ? "none" : names) + "; constants pi, e)");
  };
  std::vector<Instruction> code;
  try
  {
    code = ExpressionCompiler(text, variables).compile();
  }
  catch (const SyntaxError& e)
  {
    return failure(e.Column, e.Problem);
  }
  int depth = 0;
  int deepest = 0;
  for (const Instruction& in : code)
  {
    depth += 1 - popped(in.Code);
    deepest = depth > deepest ? depth : deepest;
  }
  if (deepest > MaxStackDepth)
  {
    return failure(0, "nests deeper than " + std::to_string(MaxStackDepth) + " pending values");
  }
  out.Text = text;
  out.What = what;
  out.Code = std::move(code);
  return Status::ok();
}

double Expression::evaluate(const double* values) const
{
  return run(this->Code.data(), this->Code.size(), values);
}

bool Expression::uses(int variable) const
{
  for (const Instruction& in : this->Code)
  {
    if (in.Code == Op::Variable && in.Variable == variable)
    {
      return true;
    }
  }
  return false;
}

} // namespace sltk
