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

/// Whether a request's Host header names this server: 127.0.0.1, localhost (any case) or [::1], with
/// the server's port. Anything else is refused: a page of another site can reach a server on 127.0.0.1
/// under a host name of its own that resolves there (DNS rebinding), and then its requests name that
/// host. An empty Host (an HTTP/1.0 request without one) is refused too.
bool is_own_host(std::string_view host, int port);

/// Whether a request's Origin header allows it to change the server's state (POST): no Origin (a
/// script, curl: not a browser page of another site), or http:// with one of the hosts above and the
/// port (the viewer's own page). A browser sends Origin with every cross-origin POST.
bool is_own_origin(std::string_view origin, int port);

}  // namespace isopatch::view
