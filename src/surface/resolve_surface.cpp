// From the command line's surface argument to a Surface: catalogue names, formulas, formula files.
#include <isopatch/catalogue.hpp>
#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>
#include <isopatch/resolve_surface.hpp>

#include "expr/suggest.hpp"

#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

namespace isopatch {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (const char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

[[noreturn]] void unknown_surface(std::string_view name) {
  std::vector<std::string> names;
  for (const CatalogueEntry& e : catalogue()) names.emplace_back(e.name);
  std::string message = "unknown surface '" + std::string(name) + "'";
  const std::string close = expr::closest_name(name, names);
  if (!close.empty()) {
    message += expr::did_you_mean(close);
  } else {
    message += " (the catalogue has";
    for (std::size_t i = 0; i < names.size(); ++i) message += (i == 0 ? " " : ", ") + names[i];
    message += ")";
  }
  throw UnknownSurfaceError(message);
}

std::string read_formula_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot read formula file '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw IoError("cannot read formula file '" + path + "'");
  return text.str();
}

Box need_box(const std::optional<Box>& box) {
  if (!box) throw InputError("a formula needs a box", "box");
  return *box;
}

}  // namespace

SurfacePtr catalogue_surface(std::string_view name, const std::map<std::string, double>& params) {
  const CatalogueEntry* entry = find_in_catalogue(name);
  if (!entry) unknown_surface(name);
  return expression_surface(std::string(entry->formula), entry->box, std::string(entry->name), params);
}

SurfacePtr resolve_surface(const std::string& spec, const std::optional<Box>& box,
                           const std::map<std::string, double>& params) {
  const std::string text = trim(spec);
  if (!text.empty() && text[0] == '@') {
    const std::string path = text.substr(1);
    const std::string formula = read_formula_file(path);
    return expression_surface(formula, need_box(box), path, params);
  }
  if (is_identifier(text)) {
    if (const CatalogueEntry* entry = find_in_catalogue(text)) {
      return expression_surface(std::string(entry->formula), box ? *box : entry->box,
                                std::string(entry->name), params);
    }
    if (text != "x" && text != "y" && text != "z" && text != "pi" && text != "e") unknown_surface(text);
  }
  return expression_surface(text, need_box(box), {}, params);
}

SurfacePtr resolve_surface_in_region(const std::string& spec, const std::optional<Box>& box,
                                     const ConvexRegion& region,
                                     const std::map<std::string, double>& params) {
  if (box || region.empty()) return resolve_surface(spec, box, params);
  const std::optional<Box> bounds = region_bounds(region);
  try {
    return resolve_surface(spec, bounds, params);
  } catch (const InputError& e) {
    if (e.setting() != "box") throw;
    throw SettingError("region",
                       "the region is unbounded: give a box as well (a formula has no box of its own)");
  }
}

}  // namespace isopatch
