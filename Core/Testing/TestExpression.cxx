// SPDX-License-Identifier: BSD-3-Clause
// Expression.h: syntax, precedence, functions, folding and the messages of bad formulas.
#include "sltk/expr/Expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace
{
const std::vector<std::string> xyt = { "x", "y", "t" };

double eval(const std::string& text, double x = 0.0, double y = 0.0, double t = 0.0)
{
  sltk::Expression e;
  const sltk::Status s = sltk::Expression::compile("f", text, xyt, e);
  EXPECT_TRUE(s.isOk()) << s.message();
  const double v[3] = { x, y, t };
  return e.evaluate(v);
}

std::string error(const std::string& text, const std::vector<std::string>& names = xyt)
{
  sltk::Expression e;
  const sltk::Status s = sltk::Expression::compile("the dynamics f_D component x", text, names, e);
  EXPECT_FALSE(s.isOk()) << text;
  EXPECT_FALSE(e.isCompiled());
  return s.message();
}
} // namespace

TEST(Expression, ArithmeticAndPrecedence)
{
  EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(eval("-2^2"), -4.0);   // power binds tighter than unary minus
  EXPECT_EQ(eval("2^3^2"), 512.0); // right-associative
  EXPECT_EQ(eval("2**3"), 8.0);
  EXPECT_EQ(eval("2^-1"), 0.5);
  EXPECT_EQ(eval("7 % 3"), 1.0);
  EXPECT_EQ(eval("10 - 4 - 3"), 3.0); // left-associative
  EXPECT_EQ(eval("8 / 4 / 2"), 1.0);
  EXPECT_EQ(eval("1e-3 * 1000"), 1.0);
  EXPECT_EQ(eval(".5 + 1."), 1.5);
  EXPECT_EQ(eval("--3"), 3.0);
  EXPECT_EQ(eval("+x", 4.0), 4.0);
}

TEST(Expression, VariablesFunctionsAndConstants)
{
  EXPECT_DOUBLE_EQ(eval("2 - y^2/2 + x", 0.25, 1.0), 1.75);
  EXPECT_DOUBLE_EQ(eval("sin(pi/2) + cos(0) + exp(0) + log(e)"), 4.0);
  EXPECT_DOUBLE_EQ(eval("atan2(1, 1)"), std::atan(1.0));
  EXPECT_DOUBLE_EQ(eval("hypot(3, 4) + sqrt(16) + abs(-1) + cbrt(27)"), 13.0);
  EXPECT_DOUBLE_EQ(eval("pow(2, 10) + fmod(7, 4) + floor(1.5) + ceil(1.5) + round(2.5) + sign(-3)"), 1032.0);
  EXPECT_EQ(eval("min(3, 1, 2)"), 1.0);
  EXPECT_EQ(eval("max(1, 5, 2, 4)"), 5.0);
  EXPECT_EQ(eval("clamp(5, 0, 2)"), 2.0);
  EXPECT_EQ(eval("clamp(-1, 0, 2)"), 0.0);
  EXPECT_EQ(eval("clamp(x, 0, 2)", 1.5), 1.5);
  EXPECT_DOUBLE_EQ(
    eval("log10(1000) + log2(8) + tanh(0) + asin(0) + acos(1) + sinh(0) + cosh(0) + tan(0) + atan(0)"), 7.0);
}

TEST(Expression, LogicAndConditionals)
{
  EXPECT_EQ(eval("x < y ? 1 : 2", 1.0, 2.0), 1.0);
  EXPECT_EQ(eval("x < y ? 1 : 2", 3.0, 2.0), 2.0);
  EXPECT_EQ(eval("if(x >= 0, x, -x)", -3.0), 3.0);
  EXPECT_EQ(eval("x > 0 ? 1 : x < 0 ? -1 : 0", -5.0), -1.0); // right-nested conditionals
  EXPECT_EQ(eval("!0 + !2"), 1.0);
  EXPECT_EQ(eval("1 && 0"), 0.0);
  EXPECT_EQ(eval("0 || 2"), 1.0);
  EXPECT_EQ(eval("x == 2", 2.0), 1.0);
  EXPECT_EQ(eval("x != 2", 2.0), 0.0);
  EXPECT_EQ(eval("x <= 2 && x > 1", 2.0), 1.0);
}

TEST(Expression, ConstantsAreFoldedAndUsesAreReported)
{
  sltk::Expression e;
  ASSERT_TRUE(sltk::Expression::compile("f", "2 * pi * (1 + 3) - max(1, 2)", xyt, e).isOk());
  EXPECT_TRUE(e.isConstant());
  EXPECT_DOUBLE_EQ(e.evaluate(nullptr), 8.0 * std::acos(-1.0) - 2.0);
  ASSERT_TRUE(sltk::Expression::compile("f", "-2 * pi * (y - 0.5)", xyt, e).isOk());
  EXPECT_FALSE(e.isConstant());
  EXPECT_TRUE(e.uses(1));
  EXPECT_FALSE(e.uses(0));
  EXPECT_EQ(e.text(), "-2 * pi * (y - 0.5)");
}

TEST(Expression, EvaluatesConcurrently)
{
  sltk::Expression e;
  ASSERT_TRUE(sltk::Expression::compile("f", "sin(x) * cos(y) + t^2", xyt, e).isOk());
  std::vector<double> sums(4, 0.0);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k)
  {
    threads.emplace_back(
      [&, k]
      {
        for (int i = 0; i < 10000; ++i)
        {
          const double v[3] = { 0.001 * i, 0.002 * i, 0.5 };
          sums[static_cast<size_t>(k)] += e.evaluate(v);
        }
      });
  }
  for (auto& t : threads)
  {
    t.join();
  }
  for (int k = 1; k < 4; ++k)
  {
    EXPECT_EQ(sums[0], sums[static_cast<size_t>(k)]);
  }
}

TEST(Expression, MessagesNameTheExpressionTheColumnAndTheProblem)
{
  std::string m = error("x + q");
  EXPECT_NE(m.find("the dynamics f_D component x"), std::string::npos) << m;
  EXPECT_NE(m.find("unknown variable 'q'"), std::string::npos) << m;
  EXPECT_NE(m.find("column 5"), std::string::npos) << m;
  EXPECT_NE(m.find("variables: x, y, t"), std::string::npos) << m;

  EXPECT_NE(error("").find("is empty"), std::string::npos);
  EXPECT_NE(error("sin(x").find("expected ')'"), std::string::npos);
  EXPECT_NE(error("2x").find("write '*'"), std::string::npos);
  EXPECT_NE(error("foo(1)").find("unknown function 'foo'"), std::string::npos);
  EXPECT_NE(error("atan2(1)").find("atan2() takes 2 arguments, got 1"), std::string::npos);
  EXPECT_NE(error("min(1)").find("at least 2 arguments"), std::string::npos);
  EXPECT_NE(error("1 +").find("ends where a value is expected"), std::string::npos);
  m = error("x = 1");
  EXPECT_NE(m.find("unexpected '='"), std::string::npos) << m;
  EXPECT_NE(m.find("column 3"), std::string::npos) << m;
  EXPECT_NE(error("x > 0 ? 1").find("expected ':'"), std::string::npos);
  EXPECT_NE(error("1..2").find("unexpected '.'"), std::string::npos);
  EXPECT_NE(error("(1 + 2))").find("unexpected ')'"), std::string::npos);

  // A slot named "" is refused (here: z in a 2D problem, a1 without controls).
  m = error("x + a1", { "x", "y", "", "t", "" });
  EXPECT_NE(m.find("unknown variable 'a1'"), std::string::npos) << m;
  EXPECT_NE(m.find("variables: x, y, t;"), std::string::npos) << m;

  std::string deep = "1";
  for (int k = 0; k < 80; ++k)
  {
    deep = "x + (" + deep + ")";
  }
  EXPECT_NE(error(deep).find("nests deeper than 64"), std::string::npos);
}
