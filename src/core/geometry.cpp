// Box helpers and the box syntax of the command line.
#include <isopatch/error.hpp>
#include <isopatch/geometry.hpp>

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace isopatch {

bool Box::valid() const {
  return lo.allFinite() && hi.allFinite() && (lo.array() < hi.array()).all();
}

bool Box::contains(const Vec3& p, double margin) const {
  return (p.array() >= lo.array() - margin).all() && (p.array() <= hi.array() + margin).all();
}

Box parse_box(const std::string& text) {
  std::vector<double> v;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    std::string item = text.substr(start, end - start);
    // Trim spaces so "-1, -1, ..." works when quoted.
    const auto first = item.find_first_not_of(" \t");
    const auto last = item.find_last_not_of(" \t");
    item = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    double value = 0.0;
    const char* b = item.data();
    const char* e = item.data() + item.size();
    if (!item.empty() && *b == '+') ++b;
    const auto [ptr, ec] = std::from_chars(b, e, value);
    if (item.empty() || ec != std::errc() || ptr != e || !std::isfinite(value))
      throw InputError("bad box '" + text + "': '" + item +
                       "' is not a finite number (want x0,y0,z0,x1,y1,z1)");
    v.push_back(value);
    start = end + 1;
  }
  if (v.size() != 6)
    throw InputError("bad box '" + text + "': want 6 numbers x0,y0,z0,x1,y1,z1, got " +
                     std::to_string(v.size()));
  Box box{Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
  for (int a = 0; a < 3; ++a)
    if (!(box.lo[a] < box.hi[a]))
      throw InputError("bad box '" + text + "': it is empty along " + std::string(1, "xyz"[a]) +
                       " (need lo < hi)");
  return box;
}

std::string format_box(const Box& box) {
  std::ostringstream out;
  out.precision(17);
  out << box.lo.x() << ',' << box.lo.y() << ',' << box.lo.z() << ',' << box.hi.x() << ',' << box.hi.y() << ','
      << box.hi.z();
  return out.str();
}

}  // namespace isopatch
