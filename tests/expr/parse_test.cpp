// Syntax of the expression language, and where and how malformed formulas are reported.
#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace isopatch {
namespace {

double eval(const std::string& formula, Vec3 p = Vec3(0.3, -0.7, 1.1)) {
  return parse_expression(formula).value(p);
}

ParseError parse_error(const std::string& formula) {
  try {
    parse_expression(formula);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no ParseError for: " << formula;
  return ParseError("none", "", 0, 0);
}

TEST(ExpressionSyntax, NumbersVariablesAndConstants) {
  EXPECT_DOUBLE_EQ(eval("1"), 1.0);
  EXPECT_DOUBLE_EQ(eval("2.5"), 2.5);
  EXPECT_DOUBLE_EQ(eval("1e-3"), 1e-3);
  EXPECT_DOUBLE_EQ(eval("2.5E+2"), 250.0);
  EXPECT_DOUBLE_EQ(eval(".5"), 0.5);
  EXPECT_DOUBLE_EQ(eval("pi"), std::numbers::pi);
  EXPECT_DOUBLE_EQ(eval("e"), std::numbers::e);
  EXPECT_DOUBLE_EQ(eval("x", Vec3(1, 2, 3)), 1.0);
  EXPECT_DOUBLE_EQ(eval("y", Vec3(1, 2, 3)), 2.0);
  EXPECT_DOUBLE_EQ(eval("z", Vec3(1, 2, 3)), 3.0);
}

TEST(ExpressionSyntax, PrecedenceAndAssociativity) {
  const Vec3 p(3.0, 2.0, 0.5);
  EXPECT_DOUBLE_EQ(eval("-x^2", p), -9.0);  // -(x^2), not (-x)^2
  EXPECT_DOUBLE_EQ(eval("-2^2"), -4.0);
  EXPECT_DOUBLE_EQ(eval("2^3^2"), 512.0);  // right-associative
  EXPECT_DOUBLE_EQ(eval("2^-1"), 0.5);
  EXPECT_DOUBLE_EQ(eval("1 + 2*3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1 + 2)*3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("8/4/2"), 1.0);  // left-associative
  EXPECT_DOUBLE_EQ(eval("8-4-2"), 2.0);
  EXPECT_DOUBLE_EQ(eval("2*-x", p), -6.0);
  EXPECT_DOUBLE_EQ(eval("x^y^z", p), std::pow(3.0, std::pow(2.0, 0.5)));
  EXPECT_DOUBLE_EQ(eval("+x - -y", p), 5.0);
}

TEST(ExpressionSyntax, EveryFunction) {
  const Vec3 p(0.3, -0.7, 1.1);
  const double x = p.x(), y = p.y(), z = p.z();
  EXPECT_DOUBLE_EQ(eval("sin(x)", p), std::sin(x));
  EXPECT_DOUBLE_EQ(eval("cos(x)", p), std::cos(x));
  EXPECT_DOUBLE_EQ(eval("tan(x)", p), std::tan(x));
  EXPECT_DOUBLE_EQ(eval("asin(x)", p), std::asin(x));
  EXPECT_DOUBLE_EQ(eval("acos(x)", p), std::acos(x));
  EXPECT_DOUBLE_EQ(eval("atan(y)", p), std::atan(y));
  EXPECT_DOUBLE_EQ(eval("atan2(y, x)", p), std::atan2(y, x));
  EXPECT_DOUBLE_EQ(eval("sinh(z)", p), std::sinh(z));
  EXPECT_DOUBLE_EQ(eval("cosh(z)", p), std::cosh(z));
  EXPECT_DOUBLE_EQ(eval("tanh(z)", p), std::tanh(z));
  EXPECT_DOUBLE_EQ(eval("exp(z)", p), std::exp(z));
  EXPECT_DOUBLE_EQ(eval("log(z)", p), std::log(z));
  EXPECT_DOUBLE_EQ(eval("sqrt(z)", p), std::sqrt(z));
  EXPECT_DOUBLE_EQ(eval("abs(y)", p), 0.7);
  EXPECT_DOUBLE_EQ(eval("min(x, y, z)", p), y);
  EXPECT_DOUBLE_EQ(eval("max(x, y, z)", p), z);
  EXPECT_DOUBLE_EQ(eval("pow(z, x)", p), std::pow(z, x));
  EXPECT_DOUBLE_EQ(eval("hypot(x, y)", p), std::hypot(x, y));
}

TEST(ExpressionSyntax, DefinitionsCommentsAndNewlines) {
  const Vec3 p(0.3, -0.7, 1.1);
  EXPECT_DOUBLE_EQ(eval("a = 2; b = a*3; b + x", p), 6.3);
  EXPECT_DOUBLE_EQ(eval("# a comment line\na = 2  # two\n\n  b = 3\na*b + x  # f\n", p), 6.3);
  // A statement continues across a newline inside parentheses, after an operator, or before a line
  // that starts with an operator.
  EXPECT_DOUBLE_EQ(eval("(x\n + 1)", p), 1.3);
  EXPECT_DOUBLE_EQ(eval("x +\n 1", p), 1.3);
  EXPECT_DOUBLE_EQ(eval("x\n  - 1", p), -0.7);
  EXPECT_DOUBLE_EQ(eval("r = 2;\n\n;x*r;;\n", p), 0.6);
  // The catalogue's torus with its definitions.
  const double torus = eval("R = 1; r = 0.4; (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)", p);
  const double q = 0.09 + 0.49 + 1.21 + 1.0 - 0.16;
  EXPECT_NEAR(torus, q * q - 4.0 * (0.09 + 0.49), 1e-12);
}

TEST(ExpressionSyntax, ParamsOverrideDefinitions) {
  const std::string torus = "R = 1; r = 0.4; (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)";
  const Vec3 p(1.3, 0.0, 0.0);  // on the torus with r = 0.3, outside the one with r = 0.4
  EXPECT_LT(parse_expression(torus).value(p), 0.0);
  EXPECT_NEAR(parse_expression(torus, {{"r", 0.3}}).value(p), 0.0, 1e-12);
  try {
    parse_expression(torus, {{"rr", 0.3}});
    FAIL() << "a parameter naming no definition must be an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rr"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean 'r'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_expression("x^2 - 1", {{"r", 1.0}}), InputError);
}

TEST(ExpressionErrors, CarryTheColumn) {
  struct Case {
    std::string formula;
    int line, column;
    std::string fragment;  // part of the reason
  };
  const Case cases[] = {
      {"x + * y", 1, 5, "expected a number"},
      {"sine(x)", 1, 1, "did you mean 'sin'?"},
      {"r = 0.4; x + rr", 1, 14, "unknown name 'rr' (did you mean 'r'?)"},
      {"(x + 1", 1, 7, "expected ')'"},
      {"sin(x", 1, 6, "expected ',' or ')'"},
      {"2x", 1, 2, "expected an operator"},
      {"x $ y", 1, 3, "unexpected character '$'"},
      {"x + 1)", 1, 6, "unmatched ')'"},
      {"atan2(x)", 1, 1, "atan2 takes 2 arguments, got 1"},
      {"min(x)", 1, 1, "at least 2"},
      {"x^2; y", 1, 6, "only the last statement"},
      {"x; a = 1", 1, 4, "before the expression"},
      {"a = 1\nb = a +* 2\na + b", 2, 8, "expected a number"},
      {"x = 1; x", 1, 1, "variable"},
      {"pi = 3; pi", 1, 1, "constant"},
      {"sin = 3; x", 1, 1, "function"},
      {"a = 1; a = 2; a", 1, 8, "already defined"},
      {"sin + 1", 1, 1, "write sin(...)"},
      {"x(1)", 1, 1, "not a function"},
      {"R = 1", 1, 6, "without an expression"},
      {"", 1, 1, "empty formula"},
      {"1e999", 1, 1, "out of range"},
      {"X + 1", 1, 1, "unknown name 'X' (did you mean 'x'?)"},
      {"a = 1\n-x^2 + a", 2, 8, "own definition (a line starting with an operator continues"},
      {"foo(x)", 1, 1, "unknown function 'foo'"},
  };
  EXPECT_EQ(parse_error("foo(x)").reason(), "unknown function 'foo'");  // too far from any name to guess
  for (const Case& c : cases) {
    const ParseError e = parse_error(c.formula);
    EXPECT_EQ(e.kind(), ErrorKind::Parse);
    EXPECT_EQ(e.line(), c.line) << c.formula << ": " << e.what();
    EXPECT_EQ(e.column(), c.column) << c.formula << ": " << e.what();
    EXPECT_NE(e.reason().find(c.fragment), std::string::npos) << c.formula << ": " << e.what();
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << "what() must be one line: " << what;
    EXPECT_NE(what.find("column " + std::to_string(c.column)), std::string::npos) << what;
  }
}

TEST(ExpressionErrors, ExcerptPutsACaretUnderTheColumn) {
  const ParseError e = parse_error("a = 1\n\tb = a +* 2\na + b");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 9);
  const std::string excerpt = e.excerpt();
  const auto newline = excerpt.find('\n');
  ASSERT_NE(newline, std::string::npos);
  EXPECT_EQ(excerpt.substr(0, newline), "\tb = a +* 2");
  // The tab is kept so the caret lines up under '*' in a terminal.
  EXPECT_EQ(excerpt.substr(newline + 1, 10), "\t       ^ ");
  EXPECT_NE(excerpt.find(e.reason()), std::string::npos);
}

TEST(ExpressionErrors, NestingDepthIsBounded) {
  const std::string deep = std::string(100000, '(') + "x" + std::string(100000, ')');
  EXPECT_THROW(parse_expression(deep), ParseError);
  const std::string fine = std::string(100, '(') + "x" + std::string(100, ')');
  EXPECT_DOUBLE_EQ(parse_expression(fine).value(Vec3(2, 0, 0)), 2.0);
}

}  // namespace
}  // namespace isopatch
