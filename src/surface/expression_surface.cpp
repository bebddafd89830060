// A Surface backed by a compiled formula: every virtual of Surface maps to one tape evaluator.
#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include <memory>
#include <utility>

namespace isopatch {
namespace {

class ExpressionSurface final : public Surface {
 public:
  ExpressionSurface(Expression expression, const Box& box, std::string name)
      : Surface(std::move(name), box), expression_(std::move(expression)) {}

  double value(const Vec3& p) const override { return expression_.value(p); }
  void values(std::span<const Vec3> points, std::span<double> out) const override {
    expression_.values(points, out);
  }
  ValueGradient value_gradient(const Vec3& p) const override { return expression_.value_gradient(p); }
  SecondOrder second_order(const Vec3& p) const override { return expression_.second_order(p); }
  std::optional<Interval> bound(const Box& box) const override { return expression_.bound(box); }
  std::optional<IntervalGradient> gradient_bound(const Box& box) const override {
    return expression_.gradient_bound(box);
  }
  std::optional<IntervalHessian> hessian_bound(const Box& box) const override {
    return expression_.hessian_bound(box);
  }
  const Expression* expression() const override { return &expression_; }

 private:
  Expression expression_;
};

/// The formula on one line, shortened: a readable default name.
std::string default_name(const std::string& formula) {
  constexpr std::size_t kLength = 60;
  std::string name;
  for (const char c : formula) {
    const bool blank = c == '\n' || c == '\r' || c == '\t' || c == ' ';
    if (!(blank && (name.empty() || name.back() == ' '))) name += blank ? ' ' : c;
  }
  while (!name.empty() && name.back() == ' ') name.pop_back();
  return name.size() <= kLength ? name : name.substr(0, kLength - 3) + "...";
}

}  // namespace

SurfacePtr expression_surface(Expression expression, const Box& box, std::string name) {
  if (!box.valid()) throw InputError("bad box " + format_box(box) + ": need finite lo < hi on every axis");
  return std::make_shared<ExpressionSurface>(std::move(expression), box, std::move(name));
}

SurfacePtr expression_surface(const std::string& formula, const Box& box, std::string name,
                              const std::map<std::string, double>& params) {
  if (!box.valid()) throw InputError("bad box " + format_box(box) + ": need finite lo < hi on every axis");
  Expression expression = parse_expression(formula, params);
  if (name.empty()) name = default_name(formula);
  return std::make_shared<ExpressionSurface>(std::move(expression), box, std::move(name));
}

}  // namespace isopatch
