#include "cli_support.hpp"

#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/resolve_surface.hpp>

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

namespace isopatch::cli {

std::map<std::string, double> parse_params(const std::vector<std::string>& items) {
  std::map<std::string, double> params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw InputError("bad --param '" + item + "' (want name=value)");
    const std::string name = item.substr(0, eq);
    const std::string text = item.substr(eq + 1);
    double value = 0.0;
    const char* b = text.data();
    const char* e = b + text.size();
    if (*b == '+') ++b;
    const auto [ptr, ec] = std::from_chars(b, e, value);
    if (ec != std::errc() || ptr != e || !std::isfinite(value))
      throw InputError("bad --param '" + item + "': '" + text + "' is not a finite number");
    if (!params.emplace(name, value).second) throw InputError("--param " + name + " is given twice");
  }
  return params;
}

SurfacePtr resolve_surface_for_mesh(const std::string& spec, const std::string& box_text,
                                    const std::vector<std::string>& params, const Mesh& mesh) {
  const std::map<std::string, double> values = parse_params(params);
  if (is_composite_path(spec)) {  // a .ipatch file: the composite as one piecewise surface
    if (!params.empty()) throw InputError("--param is for formulas, not composite surfaces (.ipatch)");
    return read_composite(spec).surface();
  }
  if (!box_text.empty()) return resolve_surface(spec, parse_box(box_text), values);
  try {
    return resolve_surface(spec, std::nullopt, values);
  } catch (const InputError& e) {
    if (e.setting() != "box" || mesh.vertex_count() == 0) throw;
  }
  Box box = bounding_box(mesh);
  const Vec3 margin = Vec3::Constant(0.01 * std::max((box.hi - box.lo).norm(), 1e-9));
  box.lo -= margin;
  box.hi += margin;
  return resolve_surface(spec, box, values);
}

void check_output_path(const std::string& path) {
  format_from_path(path);  // throws IoError for an unknown extension
  check_writable_location(path);
}

void check_writable_location(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw IoError("cannot write '" + path + "': folder '" + folder.string() + "' does not exist");
  if (::access(folder.c_str(), W_OK) != 0)
    throw IoError("cannot write '" + path + "': folder '" + folder.string() + "' is not writable");
  if (fs::is_directory(path, ec)) throw IoError("cannot write '" + path + "': it is a folder");
}

std::string group_digits(unsigned long long n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out.push_back(',');
    out.push_back(digits[i]);
  }
  return out;
}

ConvexRegion region_argument(const std::string& text) {
  if (text.empty() || text.front() != '@') return parse_region(text);
  const std::string path = text.substr(1);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read the region file '" + path + "'");
  constexpr std::size_t kMaxBytes = std::size_t{1} << 20;
  std::string content(kMaxBytes + 1, '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(in.gcount()));
  if (content.size() > kMaxBytes) throw IoError("the region file '" + path + "' is larger than 1 MiB");
  try {
    return parse_region(content);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace isopatch::cli

namespace isopatch::cli {

std::size_t default_vertex_budget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 50'000'000;
  const double bytes = static_cast<double>(pages) * static_cast<double>(page_size);
  return std::max<std::size_t>(1'000'000, static_cast<std::size_t>(bytes / kBytesPerVertexBudget));
}

}  // namespace isopatch::cli
