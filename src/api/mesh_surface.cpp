// The single entry point: dispatch on Settings::method.
#include <isopatch/fairing.hpp>
#include <isopatch/isopatch.hpp>

#include <chrono>

namespace isopatch {

Mesh mesh_surface(const Surface& surface, const Settings& settings, MeshStats* stats) {
  switch (settings.method) {
    case Method::MarchingCubes: {
      Mesh mesh = marching_cubes(surface, settings, stats);
      if (settings.fair_iterations > 0) {
        const auto start = std::chrono::steady_clock::now();
        const FairingStats fairing = laplace_fair(mesh, surface, settings.fair_iterations);
        if (stats) {
          stats->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          stats->gradient_evaluations += fairing.gradient_evaluations;
          stats->extra["fair_iterations"] = settings.fair_iterations;
          stats->extra["fair_unconverged"] = static_cast<double>(fairing.unconverged);
        }
      }
      return mesh;
    }
    case Method::Projection:
      return mesh_projection(surface, settings, stats);
  }
  throw Error(ErrorKind::Internal, "unknown method");
}

Method parse_method(const std::string& name) {
  if (name == "projection") return Method::Projection;
  if (name == "mc" || name == "marching-cubes") return Method::MarchingCubes;
  throw InputError("unknown method '" + name + "' (want projection or mc)");
}

std::string method_name(Method method) {
  switch (method) {
    case Method::Projection:
      return "projection";
    case Method::MarchingCubes:
      return "mc";
  }
  return "?";
}

}  // namespace isopatch
