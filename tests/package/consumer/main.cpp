// A user's program: mesh a sphere given as a C++ callable through the installed package, by marching
// cubes and by projection (the default method, default Settings but a coarser edge length), and check
// the installed <isopatch/version.hpp> matches the package version find_package found.
#include <isopatch/isopatch.hpp>
#include <isopatch/version.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string_view>
#include <utility>

namespace {

double max_radius_error(const isopatch::Mesh& mesh) {
  double worst = 0.0;
  for (const auto& p : mesh.positions) worst = std::fmax(worst, std::fabs(p.norm() - 1.0));
  return worst;
}

/// Closed and consistently oriented: every edge is shared by exactly two triangles, which traverse it
/// in opposite directions; and V - E + F = 2 (a sphere).
bool closed_sphere(const isopatch::Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const isopatch::Triangle& t : mesh.triangles)
    for (std::size_t i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    const auto twin = directed.find({edge.second, edge.first});
    if (count != 1 || twin == directed.end() || twin->second != 1) return false;
  }
  const long edges = static_cast<long>(directed.size() / 2);
  return static_cast<long>(mesh.vertex_count()) - edges + static_cast<long>(mesh.triangle_count()) == 2;
}

}  // namespace

int main() {
  auto sphere =
      isopatch::make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 1.0; },
                             isopatch::Box{isopatch::Vec3::Constant(-1.2), isopatch::Vec3::Constant(1.2)});
  bool ok = true;

  isopatch::Settings settings;
  settings.method = isopatch::Method::MarchingCubes;
  settings.grid = 16;
  const isopatch::Mesh mc = isopatch::mesh_surface(*sphere, settings);
  const double mc_worst = max_radius_error(mc);
  std::printf("consumer: marching cubes: %zu vertices, %zu triangles, max |r - 1| = %.3g\n",
              mc.vertex_count(), mc.triangle_count(), mc_worst);
  ok = ok && mc.vertex_count() > 100 && mc_worst < 1e-9;

  isopatch::Settings defaults;  // the default method: projection, with the whole clean-up
  defaults.edge_length = 0.1;
  const bool default_is_projection = defaults.method == isopatch::Method::Projection;
  isopatch::MeshStats stats;
  const isopatch::Mesh projected = isopatch::mesh_surface(*sphere, defaults, &stats);
  const double worst = max_radius_error(projected);
  const bool closed = closed_sphere(projected);
  std::printf("consumer: %s: %zu vertices, %zu triangles, closed %s, max |r - 1| = %.3g\n",
              isopatch::method_name(defaults.method).c_str(), projected.vertex_count(),
              projected.triangle_count(), closed ? "yes" : "no", worst);
  ok = ok && default_is_projection && projected.vertex_count() > 100 && closed && worst < 1e-9;

  std::printf("consumer: isopatch %.*s (%d.%d.%d), package %s\n", static_cast<int>(isopatch::kVersion.size()),
              isopatch::kVersion.data(), isopatch::kVersionMajor, isopatch::kVersionMinor,
              isopatch::kVersionPatch, ISOPATCH_PACKAGE_VERSION);
  ok = ok && isopatch::kVersion == std::string_view(ISOPATCH_PACKAGE_VERSION);
  return ok ? 0 : 1;
}
