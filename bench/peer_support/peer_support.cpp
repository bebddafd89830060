#include "peer_support.hpp"

#include <isopatch/error.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/resolve_surface.hpp>

#include <charconv>
#include <cmath>
#include <optional>

namespace isopatch::bench {

std::map<std::string, double> parse_params(const std::vector<std::string>& items) {
  std::map<std::string, double> params;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    double value = 0.0;
    const char* end = item.data() + item.size();
    const bool ok = eq != std::string::npos && eq > 0 && eq + 1 < item.size();
    const auto parsed = ok ? std::from_chars(item.data() + eq + 1, end, value) : std::from_chars_result{};
    if (!ok || parsed.ec != std::errc() || parsed.ptr != end || !std::isfinite(value))
      throw InputError("bad --param '" + item + "' (want name=value with a finite number)");
    if (!params.emplace(item.substr(0, eq), value).second)
      throw InputError("--param " + item.substr(0, eq) + " is given twice");
  }
  return params;
}

void SurfaceArguments::add_to(CLI::App& app) {
  app.add_option("surface", surface, "Catalogue name, formula or @file")->required();
  app.add_option("--box", box, "Region x0,y0,z0,x1,y1,z1 (a formula needs one)");
  app.add_option("--param", params, "Override a definition of the formula: name=value (repeatable)");
}

SurfacePtr SurfaceArguments::resolve() const {
  const std::optional<Box> region = box.empty() ? std::nullopt : std::optional<Box>(parse_box(box));
  return resolve_surface(surface, region, parse_params(params));
}

void OutputArguments::add_to(CLI::App& app) {
  app.add_option("-o,--output", path, "Output mesh: .ply, .obj, .off or .stl")->required();
  app.add_flag("--json", json, "Print one JSON line instead of a summary");
}

void OutputArguments::check() const {
  format_from_path(path);
}

}  // namespace isopatch::bench
