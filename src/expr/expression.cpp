// Expression: parsing glue, ParseError and the forwarding to the evaluators.
#include <isopatch/expression.hpp>

#include "expr/dag.hpp"
#include "expr/evaluate.hpp"
#include "expr/parser.hpp"

#include <cassert>

namespace isopatch {
namespace {

std::string one_line(const std::string& reason, int line, int column) {
  std::string where = line > 1 ? "line " + std::to_string(line) + ", column " : "column ";
  return "parse error at " + where + std::to_string(column) + ": " + reason;
}

}  // namespace

ParseError::ParseError(const std::string& reason, std::string source_line, int line, int column)
    : Error(ErrorKind::Parse, one_line(reason, line, column)),
      reason_(reason),
      source_line_(std::move(source_line)),
      line_(line),
      column_(column) {}

std::string ParseError::excerpt() const {
  std::string caret;
  for (int i = 0; i + 1 < column_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    caret += k < source_line_.size() && source_line_[k] == '\t' ? '\t' : ' ';
  }
  return source_line_ + "\n" + caret + "^ " + reason_;
}

double Expression::value(const Vec3& p) const {
  return expr::evaluate(*tape_, p);
}

void Expression::values(std::span<const Vec3> points, std::span<double> out) const {
  assert(points.size() == out.size());
  expr::evaluate_batch(*tape_, points, out);
}

void Expression::values(const double* x, const double* y, const double* z, double* out, std::size_t n) const {
  expr::evaluate_batch(*tape_, x, y, z, out, n);
}

ValueGradient Expression::value_gradient(const Vec3& p) const {
  return expr::evaluate_gradient(*tape_, p);
}

SecondOrder Expression::second_order(const Vec3& p) const {
  return expr::evaluate_second_order(*tape_, p);
}

Interval Expression::bound(const Box& box) const {
  return expr::evaluate_interval(*tape_, box);
}

IntervalGradient Expression::gradient_bound(const Box& box) const {
  return expr::evaluate_interval_gradient(*tape_, box);
}

IntervalHessian Expression::hessian_bound(const Box& box) const {
  return expr::evaluate_interval_hessian(*tape_, box);
}

std::size_t Expression::tape_size() const {
  return tape_->size();
}

Expression parse_expression(std::string_view formula, const std::map<std::string, double>& params) {
  expr::Dag dag;
  const expr::NodeId root = expr::parse(formula, params, dag);
  return Expression(std::make_shared<const expr::Tape>(dag.lower(root)));
}

}  // namespace isopatch
