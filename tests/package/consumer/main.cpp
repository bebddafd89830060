// A user's program: mesh a sphere given as a C++ callable through the installed package.
#include <isopatch/isopatch.hpp>

#include <cmath>
#include <cstdio>

int main() {
  auto sphere =
      isopatch::make_surface([](auto x, auto y, auto z) { return x * x + y * y + z * z - 1.0; },
                             isopatch::Box{isopatch::Vec3::Constant(-1.2), isopatch::Vec3::Constant(1.2)});
  isopatch::Settings settings;
  settings.method = isopatch::Method::MarchingCubes;
  settings.grid = 16;
  const isopatch::Mesh mesh = isopatch::mesh_surface(*sphere, settings);
  double worst = 0.0;
  for (const auto& p : mesh.positions) worst = std::fmax(worst, std::fabs(p.norm() - 1.0));
  std::printf("consumer: %zu vertices, %zu triangles, max |r - 1| = %.3g\n", mesh.vertex_count(),
              mesh.triangle_count(), worst);
  return mesh.vertex_count() > 100 && worst < 1e-9 ? 0 : 1;
}
