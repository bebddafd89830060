// Example (d): settings beyond the edge length: a convex region to mesh inside, a size field of your
// own, a budget and a fixed thread count.
//
// The unit sphere of the built-in catalogue is cut by the plane z = 0.3 (Settings::region, a list of
// half-spaces a x + b y + c z + d <= 0), so the mesh is a cap-less sphere whose boundary lies on the
// plane. A size field asks for edges three times shorter near the cut than at the south pole.
//
// Usage: isopatch_example_region_and_sizes

#include <isopatch/isopatch.hpp>         // mesh_surface(), Settings
#include <isopatch/resolve_surface.hpp>  // catalogue_surface()
#include <isopatch/topology.hpp>         // analyze_topology()

#include <algorithm>
#include <cmath>
#include <iostream>

namespace {

constexpr double kCut = 0.3;  // the plane z = kCut

// The target edge length at p: 0.04 on the plane, growing to 0.12 a distance 1 below it.
double edge_length_at(const isopatch::Vec3& p) {
  return 0.04 + 0.08 * std::clamp(kCut - p.z(), 0.0, 1.0);
}

}  // namespace

int main() {
  try {
    const isopatch::SurfacePtr sphere = isopatch::catalogue_surface("sphere");

    isopatch::Settings settings;
    settings.region = {isopatch::HalfSpace{0.0, 0.0, 1.0, -kCut}};  // z - 0.3 <= 0
    settings.size_field = edge_length_at;  // any callable; it replaces edge_length as the target
    settings.edge_length = 0.12;           // ...which then caps it
    settings.max_vertices = 200000;        // a budget: LimitError rather than a runaway mesh
    settings.threads = 2;                  // the output is the same bytes for any thread count
    settings.validate();                   // optional: mesh_surface() checks the settings too

    const isopatch::Mesh mesh = isopatch::mesh_surface(*sphere, settings);
    const isopatch::TopologyReport topology = isopatch::analyze_topology(mesh);

    // The mean edge length near the cut (both ends within 0.15 of the plane) and near the south pole.
    double highest = -1e300, near_sum = 0.0, far_sum = 0.0;
    int near_count = 0, far_count = 0;
    for (const isopatch::Vec3& p : mesh.positions) highest = std::max(highest, p.z());
    for (const isopatch::Triangle& t : mesh.triangles) {
      for (int k = 0; k < 3; ++k) {
        const isopatch::Vec3& a = mesh.positions[t[k]];
        const isopatch::Vec3& b = mesh.positions[t[(k + 1) % 3]];
        const double length = (a - b).norm();
        if (a.z() > kCut - 0.15 && b.z() > kCut - 0.15) {
          near_sum += length;
          ++near_count;
        } else if (a.z() < -0.85 && b.z() < -0.85) {
          far_sum += length;
          ++far_count;
        }
      }
    }
    std::cout << "vertices: " << mesh.vertex_count() << "\n"
              << "boundary loops: " << topology.components.at(0).boundary_loops << "\n"
              << "highest z above the plane: " << highest - kCut << "\n"
              << "mean edge near the cut: " << near_sum / std::max(near_count, 1) << "\n"
              << "mean edge near the pole: " << far_sum / std::max(far_count, 1) << "\n";
    return 0;
  } catch (const isopatch::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
