// Example (b): mesh a C++ lambda and measure the quality of the mesh.
//
// make_surface() wraps a generic callable f(x, y, z) as a Surface. It is called with doubles for values
// and with isopatch::Jet for exact gradients and Hessians (forward-mode automatic differentiation), so
// the lambda takes `auto` arguments and calls math functions unqualified (`exp(...)`, found for Jets
// by argument-dependent lookup; `using std::exp` serves doubles).
//
// Usage: isopatch_example_callable_quality

#include <isopatch/callable_surface.hpp>  // make_surface()
#include <isopatch/isopatch.hpp>          // mesh_surface(), Settings, Mesh
#include <isopatch/metrics.hpp>           // analyze_quality(): shape, valence, accuracy, topology

#include <array>
#include <iostream>

int main() {
  try {
    // Three metaballs: f = 0.4 - sum_i exp(-4 |p - c_i|^2), negative inside where the blobs merge.
    const auto blobs = [](auto x, auto y, auto z) {
      using std::exp;
      constexpr std::array<std::array<double, 3>, 3> centres{
          {{-0.45, 0.0, 0.0}, {0.45, 0.0, 0.0}, {0.0, 0.6, 0.2}}};
      decltype(x) sum = 0.0;
      for (const auto& c : centres) {
        const auto dx = x - c[0], dy = y - c[1], dz = z - c[2];
        sum += exp(-4.0 * (dx * dx + dy * dy + dz * dz));
      }
      return 0.4 - sum;
    };
    // A callable has no formula, so it cannot bound itself over a box: the mesher samples it instead.
    const isopatch::Box box{isopatch::Vec3(-1.6, -1.2, -1.2), isopatch::Vec3(1.6, 1.8, 1.4)};
    const isopatch::SurfacePtr surface = isopatch::make_surface(blobs, box, "blobs");

    isopatch::Settings settings;
    settings.edge_length = 0.08;
    const isopatch::Mesh mesh = isopatch::mesh_surface(*surface, settings);

    // Measure the mesh against the surface (docs/algorithms.md section 7): element shape, valence of
    // the interior vertices, distance of the vertices from f = 0 (relative to the mesh's diagonal) and
    // the topology (one closed component of genus 0 expected).
    const isopatch::QualityReport q = isopatch::analyze_quality(mesh, surface.get());
    std::cout << "vertices: " << mesh.vertex_count() << "\n"
              << "components: " << q.topology.components.size() << "\n"
              << "watertight: " << q.topology.watertight() << "\n"
              << "genus: " << q.topology.genus << "\n"
              << "smallest angle: " << q.shape.min_angle.min << "\n"
              << "median smallest angle: " << q.shape.min_angle.median << "\n"
              << "valence 6 share: " << q.valence.share_6 << "\n"
              << "largest vertex distance: " << q.accuracy->vertex_distance.max / q.accuracy->diagonal
              << "\n";
    return 0;
  } catch (const isopatch::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
