// The benchmark surfaces of docs/algorithms.md 7.4 as formulas, with their boxes and genera.
#include <isopatch/catalogue.hpp>

#include "core/edit_distance.hpp"

#include <algorithm>
#include <array>
#include <numbers>

namespace isopatch {
namespace {

Box box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return Box{Vec3(x0, y0, z0), Vec3(x1, y1, z1)};
}

const std::array<CatalogueEntry, 11>& entries() {
  static const std::array<CatalogueEntry, 11> table = {{
      {"sphere", "x^2 + y^2 + z^2 - 1", "unit sphere", box(-1.2, -1.2, -1.2, 1.2, 1.2, 1.2), 0, 1, true,
       true},
      {"ellipsoid", "x^2 + 2*y^2 + 4*z^2 - 1", "ellipsoid with semi-axes 1, 0.707, 0.5",
       box(-1.2, -0.9, -0.7, 1.2, 0.9, 0.7), 0, 1, true, true},
      {"torus", "R = 1; r = 0.4; (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)",
       "ring torus, R = 1, r = 0.4", box(-1.6, -1.6, -0.6, 1.6, 1.6, 0.6), 1, 1, true, true},
      {"tanglecube", "x^4 - 5*x^2 + y^4 - 5*y^2 + z^4 - 5*z^2 + 11.8", "tangle cube (genus 5)",
       box(-2.6, -2.6, -2.6, 2.6, 2.6, 2.6), 5, 1, true, true},
      {"genus2", "((x^2 + y^2)^2 - x^2 + y^2)^2 + z^2 - 0.01", "thin genus-2 surface around a lemniscate",
       box(-1.2, -0.5, -0.15, 1.2, 0.5, 0.15), 2, 1, true, true},
      {"double_torus", "(x*(x - 1)^2*(x - 2) + y^2)^2 + z^2 - 0.01", "thin double torus",
       box(-0.2, -0.7, -0.15, 2.2, 0.7, 0.15), 2, 1, true, true},
      {"chmutov6",
       "T6x = 32*x^6 - 48*x^4 + 18*x^2 - 1; T6y = 32*y^6 - 48*y^4 + 18*y^2 - 1;\n"
       "T6z = 32*z^6 - 48*z^4 + 18*z^2 - 1; T6x + T6y + T6z",
       "Chmutov surface of degree 6 (Chebyshev polynomials)", box(-1.1, -1.1, -1.1, 1.1, 1.1, 1.1), 28, 1,
       true, true},
      {"gyroid", "sin(x)*cos(y) + sin(y)*cos(z) + sin(z)*cos(x)", "gyroid, clipped by its box (open)",
       box(-std::numbers::pi, -std::numbers::pi, -std::numbers::pi, std::numbers::pi, std::numbers::pi,
           std::numbers::pi),
       -1, 1, false, true},
      {"blobby",
       "0.5 - exp(-4*((x + 0.5)^2 + y^2 + z^2)) - exp(-4*((x - 0.5)^2 + y^2 + z^2))"
       " - exp(-6*(x^2 + (y - 0.6)^2 + (z - 0.3)^2))",
       "three blended Gaussian blobs", box(-1.1, -0.6, -0.6, 1.1, 1.1, 0.8), 0, 1, true, true},
      {"cassini", "((x - 1)^2 + y^2 + z^2)*((x + 1)^2 + y^2 + z^2) - 1.01^4",
       "Cassini oval surface with a thin neck", box(-1.6, -0.65, -0.65, 1.6, 0.65, 0.65), 0, 1, true, true},
      {"heart", "(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3",
       "Taubin's heart, singular at (0,0,+-1)", box(-1.3, -0.8, -1.2, 1.3, 0.8, 1.4), 0, 1, true, false},
  }};
  return table;
}

}  // namespace

std::span<const CatalogueEntry> catalogue() {
  return entries();
}

const CatalogueEntry* find_in_catalogue(std::string_view name) {
  for (const CatalogueEntry& e : entries())
    if (e.name == name) return &e;
  return nullptr;
}

std::vector<std::string> closest_catalogue_names(std::string_view name, std::size_t count) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const CatalogueEntry& e : entries())
    scored.emplace_back(edit_distance(name, e.name), std::string(e.name));
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scored.size() && i < count; ++i) out.push_back(scored[i].second);
  return out;
}

}  // namespace isopatch
