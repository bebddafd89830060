// parse_mesh_request (view_request.hpp): JSON -> MeshRequest, every member checked by type.
#include "view/view_request.hpp"

#include <isopatch/error.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace isopatch::view {
namespace {

using nlohmann::json;

/// `text` as it may stand in a one-line message: control characters escaped (\n, \xHH), at most 60
/// characters (a client's member names are echoed).
std::string printable(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char c : text) {
    if (out.size() >= 60) return out + "...";
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (u < 0x20 || u == 0x7f) {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

[[noreturn]] void bad(const std::string& member, const std::string& problem) {
  throw InputError(printable(member) + ": " + problem, member);
}

double positive_number(const json& value, const std::string& member) {
  if (!value.is_number()) bad(member, "must be a number");
  const double x = value.get<double>();
  if (!std::isfinite(x) || x <= 0.0) bad(member, "must be a finite number > 0");
  return x;
}

std::size_t count(const json& value, const std::string& member, std::size_t largest) {
  if (!value.is_number_integer() && !value.is_number_unsigned()) bad(member, "must be an integer");
  if (value.is_number_integer() && value.get<long long>() < 0) bad(member, "must not be negative");
  const auto n = value.get<unsigned long long>();
  if (n > largest) bad(member, "must be at most " + std::to_string(largest));
  return static_cast<std::size_t>(n);
}

Box parse_box_member(const json& value) {
  if (!value.is_array() || value.size() != 6)
    bad("box", "must be an array of 6 numbers x0, y0, z0, x1, y1, z1");
  std::array<double, 6> c{};
  for (std::size_t i = 0; i < 6; ++i) {
    if (!value[i].is_number()) bad("box", "must be an array of 6 numbers x0, y0, z0, x1, y1, z1");
    c[i] = value[i].get<double>();
  }
  return Box{Vec3(c[0], c[1], c[2]), Vec3(c[3], c[4], c[5])};
}

}  // namespace

MeshRequest parse_mesh_request(std::string_view body, const RequestLimits& limits) {
  if (body.size() > limits.max_request_bytes)
    bad("request", "longer than " + std::to_string(limits.max_request_bytes) + " bytes");
  const json j = json::parse(body.begin(), body.end(), nullptr, false);
  if (j.is_discarded()) bad("request", "not valid JSON");
  if (!j.is_object()) bad("request", "must be a JSON object");

  MeshRequest request;
  Settings& s = request.settings;
  s.quality = Quality::Preview;
  s.max_vertices = limits.max_vertices;
  s.time_limit = limits.time_limit;
  bool has_surface = false;
  for (const auto& [key, value] : j.items()) {
    if (value.is_null()) continue;
    if (key == "surface") {
      if (!value.is_string()) bad(key, "must be a string");
      request.surface = value.get<std::string>();
      if (request.surface.size() > limits.max_surface_chars)
        bad(key, "longer than " + std::to_string(limits.max_surface_chars) + " characters");
      if (!request.surface.empty() && request.surface.front() == '@')
        bad(key, "@file is not served: type the formula");
      has_surface = true;
    } else if (key == "box") {
      s.box = parse_box_member(value);
    } else if (key == "edge_length") {
      s.edge_length = positive_number(value, key);
    } else if (key == "max_error") {
      s.max_error = positive_number(value, key);
    } else if (key == "quality") {
      if (!value.is_string()) bad(key, "must be \"preview\", \"default\" or \"fine\"");
      s.quality = parse_quality(value.get<std::string>());
    } else if (key == "method") {
      if (value == "projection")
        s.method = Method::Projection;
      else if (value == "mc")
        s.method = Method::MarchingCubes;
      else
        bad(key, "must be \"projection\" or \"mc\"");
    } else if (key == "creases") {
      if (value != "auto" && value != "off") bad(key, "must be \"auto\" or \"off\"");
      s.creases = parse_creases(value.get<std::string>());
    } else if (key == "remesh") {
      s.remesh_iterations = static_cast<int>(count(value, key, 100));
    } else if (key == "threads") {
      s.threads = static_cast<int>(count(value, key, kMaxThreads));
    } else if (key == "time_limit") {
      s.time_limit = std::min(positive_number(value, key), limits.time_limit);
    } else if (key == "max_vertices") {
      // 0 asks for no limit, so it gets the server's; anything else at most the server's.
      const std::size_t n = count(value, key, std::numeric_limits<std::size_t>::max());
      s.max_vertices =
          n == 0 || (limits.max_vertices != 0 && n > limits.max_vertices) ? limits.max_vertices : n;
    } else {
      bad(key,
          "unknown member (want surface, box, edge_length, max_error, quality, method, creases, remesh, "
          "threads, time_limit, max_vertices)");
    }
  }
  if (!has_surface || request.surface.empty()) bad("surface", "missing: give a catalogue name or a formula");
  s.validate();
  return request;
}

bool is_own_host(std::string_view host, int port) {
  std::string suffix = ":";  // appended: GCC 12 warns wrongly about "literal" + std::string
  suffix += std::to_string(port);
  if (host.size() <= suffix.size() || host.substr(host.size() - suffix.size()) != suffix) return false;
  std::string name(host.substr(0, host.size() - suffix.size()));
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name == "127.0.0.1" || name == "localhost" || name == "[::1]";
}

bool is_own_origin(std::string_view origin, int port) {
  constexpr std::string_view scheme = "http://";
  if (origin.empty()) return true;
  return origin.starts_with(scheme) && is_own_host(origin.substr(scheme.size()), port);
}

}  // namespace isopatch::view
