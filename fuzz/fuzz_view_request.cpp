// libFuzzer target: what a client of `isopatch view` sends. The bytes are a POST /api/mesh body for
// parse_mesh_request (which must accept it within the server's budget or throw an isopatch::Error, and
// nothing else), and a URL path for is_safe_url_path (which must never pass a path that climbs out).
#include <isopatch/error.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "view/static_files.hpp"
#include "view/view_request.hpp"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

// Independent of is_safe_url_path's loop: after the leading '/' and one trailing '/', is any
// '/'-separated segment "..", "." or empty?
bool has_bad_segment(std::string_view path) {
  std::string_view p = path.substr(1);
  if (!p.empty() && p.back() == '/') p.remove_suffix(1);
  if (p.empty()) return false;
  std::string segment;
  for (const char c : std::string(p) + "/") {
    if (c != '/') {
      segment.push_back(c);
      continue;
    }
    if (segment.empty() || segment == "." || segment == "..") return true;
    segment.clear();
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  isopatch::view::RequestLimits limits;
  limits.max_vertices = 5000;
  limits.time_limit = 2.0;
  try {
    const isopatch::view::MeshRequest r = isopatch::view::parse_mesh_request(bytes, limits);
    check(!r.surface.empty() && r.surface.front() != '@');
    check(r.settings.max_vertices >= 1 && r.settings.max_vertices <= limits.max_vertices);
    check(r.settings.time_limit > 0.0 && r.settings.time_limit <= limits.time_limit);
    r.settings.validate();  // must not throw: the parser validated
  } catch (const isopatch::Error& e) {
    check(std::string(e.what()).find('\n') == std::string::npos);
  }
  if (isopatch::view::is_safe_url_path(bytes)) {
    check(bytes.front() == '/');
    check(bytes.find('\\') == std::string_view::npos && bytes.find('\0') == std::string_view::npos);
    check(!has_bad_segment(bytes));
  }
  return 0;
}
