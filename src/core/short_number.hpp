#pragma once
// A number as error messages print it: six significant digits ("0.15", "1e-07"), so a level or a range
// reads at a glance.

#include <sstream>
#include <string>

namespace isopatch {

/// `v` with six significant digits, as std::ostream prints it by default.
inline std::string short_number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace isopatch
