// Parsing and checks of regions and frames (convex_region.hpp).
#include <isopatch/convex_region.hpp>
#include <isopatch/error.hpp>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>

namespace isopatch {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

/// Comma-separated finite numbers, or an empty vector when any is not one.
std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::string t = trim(item);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v)) return {};
    out.push_back(v);
  }
  if (!text.empty() && text.back() == ',') return {};
  return out;
}

/// Text for a one-line message: at most 40 characters, control characters as '?'.
std::string shown(const std::string& text) {
  std::string s = text.substr(0, 40);
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 32 || c == 127) c = '?';
  return text.size() > 40 ? s + "..." : s;
}

std::string plane_problem(const HalfSpace& h) {
  if (!std::isfinite(h.a) || !std::isfinite(h.b) || !std::isfinite(h.c) || !std::isfinite(h.d))
    return "has a coefficient that is not a finite number";
  if (h.a == 0.0 && h.b == 0.0 && h.c == 0.0) return "has no normal (a = b = c = 0)";
  return "";
}

}  // namespace

ConvexRegion parse_region(const std::string& text) {
  ConvexRegion region;
  std::string normalised = text;
  for (char& ch : normalised)
    if (ch == ';') ch = '\n';
  std::stringstream in(normalised);
  std::string line;
  while (std::getline(in, line)) {
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    const std::vector<double> v = numbers(t);
    const std::string index = std::to_string(region.size() + 1);
    if (v.size() != 4)
      throw InputError("region: plane " + index + " ('" + t +
                       "') is not four numbers a,b,c,d (a x + b y + c z + d <= 0)");
    const HalfSpace h{v[0], v[1], v[2], v[3]};
    if (const std::string problem = plane_problem(h); !problem.empty())
      throw InputError("region: plane " + index + " " + problem);
    region.push_back(h);
    if (region.size() > kMaxRegionPlanes)
      throw InputError("region: more than " + std::to_string(kMaxRegionPlanes) + " planes");
  }
  if (region.empty()) throw InputError("region: no plane given (want a,b,c,d;a,b,c,d;...)");
  return region;
}

void validate_region(const ConvexRegion& region, const char* setting) {
  if (region.size() > kMaxRegionPlanes)
    throw SettingError(setting, "a region or cell has at most " + std::to_string(kMaxRegionPlanes) +
                                    " planes, got " + std::to_string(region.size()));
  for (std::size_t i = 0; i < region.size(); ++i)
    if (const std::string problem = plane_problem(region[i]); !problem.empty())
      throw SettingError(setting, "plane " + std::to_string(i + 1) + " of the region " + problem);
}

Mat3 Frame::rotation() const {
  const double k = std::numbers::pi / 180.0;
  const Mat3 z = Eigen::AngleAxisd(azimuth * k, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 y = Eigen::AngleAxisd(-elevation * k, Vec3::UnitY()).toRotationMatrix();
  const Mat3 x = Eigen::AngleAxisd(roll * k, Vec3::UnitX()).toRotationMatrix();
  return z * y * x;
}

Frame parse_frame(const std::string& text) {
  const std::vector<double> v = numbers(trim(text));
  if (v.size() != 3)
    throw InputError("frame: want three angles in degrees AZ,EL,ROLL, got '" + shown(text) + "'");
  return Frame{v[0], v[1], v[2]};
}

ConvexRegion box_planes(const Box& box) {
  return {{-1, 0, 0, box.lo.x()}, {1, 0, 0, -box.hi.x()}, {0, -1, 0, box.lo.y()},
          {0, 1, 0, -box.hi.y()}, {0, 0, -1, box.lo.z()}, {0, 0, 1, -box.hi.z()}};
}

}  // namespace isopatch
