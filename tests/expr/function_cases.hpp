#pragma once
// Formulas exercising every function and operator of the language, each with a box where it is
// defined and smooth, shared by the derivative, interval and printing tests.

#include <isopatch/geometry.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace isopatch::test {

struct FunctionCase {
  std::string formula;
  Box box = Box{Vec3::Constant(-1.0), Vec3::Constant(1.0)};
  /// Distance to a kink (abs, min, max) at a point; central differences skip points near one.
  std::function<double(const Vec3&)> kink = nullptr;
};

inline std::vector<FunctionCase> function_cases() {
  const Box unit{Vec3::Constant(-1.0), Vec3::Constant(1.0)};
  return {
      {"x + y*z - 3"},
      {"x - y/(2 + y*z)"},
      {"-x^2 + y^2*z"},
      {"x^3*y - z^5 + 2*x^4"},
      {"(x + 2)^-2 + (y + 3)^-3"},
      {"(2 + x*y)^1.5 - (3 + z)^-0.5"},
      {"sin(x*y + z)"},
      {"cos(x - 2*y*z)"},
      {"tan(0.4*x + 0.3*y*z)"},
      {"asin(0.3*x*y + 0.2*z)"},
      {"acos(0.3*x - 0.4*y*z)"},
      {"atan(x*y + z^2)"},
      {"atan2(x + y*z, 2 + x*y)"},
      {"atan2(2 + x*y, z - x)"},
      {"sinh(x*y - z)"},
      {"cosh(x + y*z)"},
      {"tanh(2*x - y*z)"},
      {"exp(x*y - z^2)"},
      {"log(3 + x*y + z)"},
      {"sqrt(3 + x*y + z)"},
      {"abs(x*y + 0.5*z)", unit, [](const Vec3& p) { return std::fabs(p.x() * p.y() + 0.5 * p.z()); }},
      {"min(x*y, z^2 - 0.5)", unit,
       [](const Vec3& p) { return std::fabs(p.x() * p.y() - (p.z() * p.z() - 0.5)); }},
      {"max(x + y, z*x, 0.2)", unit,
       [](const Vec3& p) {
         const double a = p.x() + p.y(), b = p.z() * p.x(), c = 0.2;
         return std::min({std::fabs(a - b), std::fabs(a - c), std::fabs(b - c)});
       }},
      {"pow(2 + x, y*z)"},
      {"pow(x*x + 1, 0.5*y)"},
      {"2^x + e^(y*z) + x^y", Box{Vec3(0.5, -1.0, -1.0), Vec3(2.0, 1.0, 1.0)}},
      {"hypot(x*y + 1.5, z - y)"},
      {"R = 1; r = 0.4; (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)"},
      {"a = sin(x); b = a*a + cos(y)*a; b/(2 + z) - a"},
  };
}

}  // namespace isopatch::test
