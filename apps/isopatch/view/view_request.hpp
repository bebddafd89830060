#pragma once
// The body of the viewer's POST /api/mesh: what to mesh and how, as JSON, turned into Settings with
// the server's bounds. Depends on core only (and nlohmann_json), so that it can be fuzzed alone
// (fuzz/fuzz_view_request.cpp).

#include <isopatch/settings.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace isopatch::view {

/// The bounds the server puts on every run, whatever a request asks for.
struct RequestLimits {
  std::size_t max_request_bytes = 64 * 1024;  ///< the whole body
  std::size_t max_surface_chars = 16 * 1024;  ///< the formula or name
  std::size_t max_vertices = 400000;          ///< Settings::max_vertices (a request may ask for fewer)
  double time_limit = 30.0;                   ///< seconds, Settings::time_limit (a request may ask for less)
};

/// A parsed request: the surface as the command line takes it (catalogue name, formula; never
/// @file, which would read files of the server's choosing) and the settings to mesh it with.
struct MeshRequest {
  std::string surface;
  Settings settings;
};

/// Parses `body`, a JSON object with the members (all optional but "surface")
///   "surface": string, "box": [x0, y0, z0, x1, y1, z1], "edge_length": number > 0,
///   "max_error": number > 0, "quality": "preview" | "default" | "fine" (default preview, for
///   liveness), "method": "projection" | "mc", "creases": "auto" | "off" (a CSG formula meshed along
///   its creases, or as a smooth surface), "remesh": integer 0..100 (clean-up rounds; 0: the paper's
///   method alone), "threads": integer 0..kMaxThreads, "time_limit": seconds > 0, "max_vertices": integer >=
///   0
/// (null stands for "not given"). The result's settings hold the values, the limits' budgets (the
/// smaller of the two where a request asks too) and pass Settings::validate().
/// \throw InputError (setting() names the member) for a body that is too long, is not a JSON object,
///        lacks the surface or has a member of the wrong type, an unknown member, a surface that
///        starts with '@' or is too long; SettingError from Settings::validate().
MeshRequest parse_mesh_request(std::string_view body, const RequestLimits& limits = {});

}  // namespace isopatch::view
