// The single entry point: dispatch on Settings::method.
#include <isopatch/isopatch.hpp>

namespace isopatch {

Mesh mesh_surface(const Surface& surface, const Settings& settings, MeshStats* stats) {
  switch (settings.method) {
    case Method::MarchingCubes: return marching_cubes(surface, settings, stats);
    case Method::Projection: break;
  }
  throw InputError("method 'projection' is not available in this build yet; use --method mc");
}

Method parse_method(const std::string& name) {
  if (name == "projection") return Method::Projection;
  if (name == "mc" || name == "marching-cubes") return Method::MarchingCubes;
  throw InputError("unknown method '" + name + "' (want projection or mc)");
}

std::string method_name(Method method) {
  switch (method) {
    case Method::Projection: return "projection";
    case Method::MarchingCubes: return "mc";
  }
  return "?";
}

}  // namespace isopatch
