// libFuzzer target: a formula of the expression language. Parsing must either succeed or throw
// ParseError / InputError with a one-line message; a compiled formula is evaluated at a few points
// (point, batch, gradient, Hessian), bounded over a few boxes, printed and parsed back. Nothing may
// crash, and the interval bound must hold the point values where they are finite.
#include <isopatch/expression.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

void exercise(const isopatch::Expression& f) {
  using isopatch::Box;
  using isopatch::Vec3;
  const Vec3 points[] = {Vec3(0, 0, 0), Vec3(0.5, -0.25, 0.125), Vec3(-1, 1, -1), Vec3(1e-9, 2.5, -3),
                         Vec3(1, 1, 1)};
  std::vector<Vec3> batch(std::begin(points), std::end(points));
  std::vector<double> out(batch.size());
  f.values(batch, out);
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const double v = f.value(batch[i]);
    (void)f.value_gradient(batch[i]);
    (void)f.second_order(batch[i]);
    // Batch and point evaluation agree (both NaN, or equal).
    check((std::isnan(v) && std::isnan(out[i])) || v == out[i] ||
          std::abs(v - out[i]) <= 1e-9 * (1 + std::abs(v)));
  }
  const Box boxes[] = {Box{Vec3(-1, -1, -1), Vec3(1, 1, 1)}, Box{Vec3(0.25, -0.5, 0.0), Vec3(0.75, 0.0, 0.5)},
                       Box{Vec3(-3, 2, -3), Vec3(1e-9, 2.5, 1e-9)}};
  for (const Box& box : boxes) {
    const isopatch::Interval bound = f.bound(box);
    (void)f.gradient_bound(box);
    // Soundness: the point values inside the box are inside the bound.
    for (const Vec3& p : points) {
      if (!box.contains(p)) continue;
      const double v = f.value(p);
      if (!std::isfinite(v)) continue;
      check(bound.lo <= v + 1e-9 * (1 + std::abs(v)) && v - 1e-9 * (1 + std::abs(v)) <= bound.hi);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;  // long formulas only slow the search down
  const std::string_view formula(reinterpret_cast<const char*>(data), size);
  try {
    const isopatch::Expression f = isopatch::parse_expression(formula);
    exercise(f);
    // Printing and parsing back gives a formula that compiles too.
    const isopatch::Expression g = isopatch::parse_expression(isopatch::to_string(f));
    exercise(g);
  } catch (const isopatch::Error& e) {
    const std::string message = e.what();
    check(!message.empty() && message.find('\n') == std::string::npos);
  }
  return 0;
}
