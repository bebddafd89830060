#pragma once
/// \file expression.hpp
/// The expression language: a formula f(x, y, z) compiled once to an immutable tape and evaluated in
/// several ways (one point, a batch, value with gradient and Hessian, interval bounds over a box).
///
/// Syntax (the grammar is at the top of src/expr/parser.cpp):
///   numbers 1, 2.5, 1e-3; variables x y z; constants pi e; + - * / ^ with the usual precedence,
///   `^` right-associative and binding tighter than unary minus (-x^2 = -(x^2), 2^3^2 = 512);
///   functions sin cos tan asin acos atan atan2 sinh cosh tanh exp log sqrt abs min max pow hypot;
///   definitions `name = expr` separated by `;` or newlines, the last statement being f itself;
///   `#` starts a comment. A newline inside parentheses, after an operator, or before a line that
///   starts with + - * / ^ continues the statement. (`@file` and catalogue names are resolved by
///   resolve_surface.hpp.)
///
/// Compilation: a DAG with shared common subexpressions and folded constants, then a flat tape
/// (libfive's tape design, M. Keeter, "Massively parallel rendering of complex closed-form implicit
/// surfaces", SIGGRAPH 2020). Derivatives are forward-mode (exact, no differences); intervals follow
/// interval_math.hpp (Moore, Kearfott & Cloud 2009) and are sound.
///
/// An Expression is cheap to copy (it shares the tape) and safe to evaluate from many threads.

#include <isopatch/derivatives.hpp>
#include <isopatch/error.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/interval.hpp>

#include <cstddef>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace isopatch {

namespace expr {
struct Tape;
}

/// A malformed formula. what() is one line naming the place ("parse error at column 7: ...");
/// excerpt() renders the offending line with a caret under the column, for a terminal.
class ParseError : public Error {
 public:
  /// \param reason       what is wrong, without the place
  /// \param source_line  the text of that line (without newline)
  /// \param line,column  1-based
  ParseError(const std::string& reason, std::string source_line, int line, int column);
  int line() const noexcept { return line_; }
  int column() const noexcept { return column_; }
  const std::string& reason() const noexcept { return reason_; }
  /// Two lines: the source line, then a caret under the column followed by the reason.
  std::string excerpt() const;

 private:
  std::string reason_;
  std::string source_line_;
  int line_;
  int column_;
};

class Expression {
 public:
  /// f(p); NaN or infinity where the formula is undefined (the caller reports it).
  double value(const Vec3& p) const;
  /// out[i] = f(points[i]). \pre out.size() == points.size()
  void values(std::span<const Vec3> points, std::span<double> out) const;
  /// out[i] = f(x[i], y[i], z[i]) for i < n, structure-of-arrays form (the fastest).
  void values(const double* x, const double* y, const double* z, double* out, std::size_t n) const;
  ValueGradient value_gradient(const Vec3& p) const;
  SecondOrder second_order(const Vec3& p) const;
  /// A sound enclosure of f over the box: it holds f(p) for every p in the box where f is defined
  /// (empty when f is defined nowhere in it).
  Interval bound(const Box& box) const;
  /// Sound enclosures of f and of its gradient over the box (forward mode on intervals).
  IntervalGradient gradient_bound(const Box& box) const;
  /// Sound enclosures of f, its gradient and its Hessian over the box (second-order forward mode on
  /// intervals; see IntervalHessian for the entries that are the whole line).
  IntervalHessian hessian_bound(const Box& box) const;

  /// Instructions plus constants of the compiled program (shared subexpressions count once).
  std::size_t tape_size() const;
  const expr::Tape& tape() const { return *tape_; }

  explicit Expression(std::shared_ptr<const expr::Tape> tape) : tape_(std::move(tape)) {}

 private:
  std::shared_ptr<const expr::Tape> tape_;
};

/// Compiles a formula. `params` overrides definitions: params["r"] = 0.3 replaces the value of
/// `r = ...` (the definition must still parse).
/// \throw ParseError for a malformed formula (unknown names suggest the closest known one)
/// \throw InputError when a parameter names no definition of the formula
Expression parse_expression(std::string_view formula, const std::map<std::string, double>& params = {});

/// The compiled formula written back in the expression language: shared subexpressions become
/// definitions, constants print with 17 digits, so parsing the text gives the same values.
std::string to_string(const Expression& expression);

}  // namespace isopatch
