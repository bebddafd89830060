// parse_mesh_request: the viewer's JSON body -> Settings, within the server's bounds.
#include <isopatch/error.hpp>

#include <gtest/gtest.h>

#include "view/view_request.hpp"

namespace isopatch::view {
namespace {

std::string setting_of(const std::string& body) {
  try {
    parse_mesh_request(body);
  } catch (const Error& e) {
    return e.setting();
  }
  return "(accepted)";
}

TEST(ViewRequest, ReadsEveryMember) {
  const MeshRequest r = parse_mesh_request(
      R"({"surface": "x^2+y^2+z^2-1", "box": [-2, -2, -2, 2, 2, 2], "edge_length": 0.1, "max_error": 0.001,
          "quality": "fine", "method": "mc", "creases": "off", "remesh": 0, "threads": 1, "time_limit": 5, "max_vertices": 1000})");
  EXPECT_EQ(r.surface, "x^2+y^2+z^2-1");
  ASSERT_TRUE(r.settings.box.has_value());
  EXPECT_EQ(r.settings.box->lo, Vec3(-2, -2, -2));
  EXPECT_EQ(r.settings.box->hi, Vec3(2, 2, 2));
  EXPECT_EQ(r.settings.edge_length, 0.1);
  EXPECT_EQ(r.settings.max_error, 0.001);
  EXPECT_EQ(r.settings.quality, Quality::Fine);
  EXPECT_EQ(r.settings.method, Method::MarchingCubes);
  EXPECT_EQ(r.settings.creases, Creases::Off);
  EXPECT_EQ(parse_mesh_request(R"({"surface": "torus"})").settings.creases, Creases::Automatic);
  EXPECT_THROW(parse_mesh_request(R"({"surface": "torus", "creases": "sharp"})"), InputError);
  EXPECT_THROW(parse_mesh_request(R"({"surface": "torus", "creases": 1})"), InputError);
  EXPECT_EQ(r.settings.remesh_iterations, 0);
  EXPECT_EQ(r.settings.threads, 1);
  EXPECT_EQ(r.settings.time_limit, 5.0);
  EXPECT_EQ(r.settings.max_vertices, 1000u);
}

TEST(ViewRequest, DefaultsToPreviewWithinTheServerBudget) {
  RequestLimits limits;
  limits.max_vertices = 5000;
  limits.time_limit = 3.0;
  const MeshRequest r = parse_mesh_request(R"({"surface": "torus", "box": null, "time_limit": 100,
                                               "max_vertices": 9999999})",
                                           limits);
  EXPECT_EQ(r.settings.quality, Quality::Preview);
  EXPECT_FALSE(r.settings.box.has_value());
  EXPECT_EQ(r.settings.time_limit, 3.0) << "a request cannot raise the time limit";
  EXPECT_EQ(r.settings.max_vertices, 5000u) << "nor the vertex budget";
}

TEST(ViewRequest, RefusesBadBodiesNamingTheMember) {
  EXPECT_EQ(setting_of("not json"), "request");
  EXPECT_EQ(setting_of("[1, 2]"), "request");
  EXPECT_EQ(setting_of("{}"), "surface");
  EXPECT_EQ(setting_of(R"({"surface": ""})"), "surface");
  EXPECT_EQ(setting_of(R"({"surface": 3})"), "surface");
  EXPECT_EQ(setting_of(R"({"surface": "@/etc/passwd"})"), "surface");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "box": [1, 2, 3]})"), "box");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "box": [1, 1, 1, 0, 0, 0]})"), "box");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "edge_length": -1})"), "edge_length");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "edge_length": "small"})"), "edge_length");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "max_error": 0})"), "max_error");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "quality": "best"})"), "quality");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "method": "magic"})"), "method");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "remesh": 101})"), "remesh");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "threads": -1})"), "threads");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "threads": 1.5})"), "threads");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "colour": "red"})"), "colour");
  EXPECT_EQ(setting_of(R"({"surface": "torus", "edge_length": 1e-9})"), "(accepted)")
      << "tiny sizes are bounded by the budget, not refused";
  RequestLimits small;
  small.max_request_bytes = 10;
  EXPECT_THROW(parse_mesh_request(R"({"surface": "torus"})", small), InputError);
  small = {};
  small.max_surface_chars = 3;
  EXPECT_THROW(parse_mesh_request(R"({"surface": "torus"})", small), InputError);
}

TEST(ViewRequest, EchoedMemberNamesStayOnOneLine) {
  // A member name with a newline (found by fuzz_view_request) or a very long one is escaped and cut.
  for (const char* body :
       {R"({"surface": "torus", "su1\nnror": 1})", R"({"surface": "torus", "a\u0007b": 1})"}) {
    try {
      parse_mesh_request(body);
      ADD_FAILURE() << "accepted " << body;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(message.find('\a'), std::string::npos) << message;
    }
  }
  try {
    parse_mesh_request(R"({"surface": "torus", ")" + std::string(500, 'k') + R"(": 1})");
    ADD_FAILURE() << "accepted a long unknown member";
  } catch (const InputError& e) {
    EXPECT_LT(std::string(e.what()).size(), 250u);
  }
}

TEST(ViewRequest, OwnHostAndOriginAreTheLoopbackNamesWithThePort) {
  EXPECT_TRUE(is_own_host("127.0.0.1:8080", 8080));
  EXPECT_TRUE(is_own_host("LOCALHOST:8080", 8080));
  EXPECT_TRUE(is_own_host("[::1]:8080", 8080));
  for (const char* host : {"", "127.0.0.1", "127.0.0.1:80", "127.0.0.1:18080", "localhost.evil.example:8080",
                           "evil.example:8080", "127.0.0.2:8080", ":8080", "127.0.0.1:8080:8080"})
    EXPECT_FALSE(is_own_host(host, 8080)) << host;
  EXPECT_TRUE(is_own_origin("", 8080));
  EXPECT_TRUE(is_own_origin("http://localhost:8080", 8080));
  for (const char* origin :
       {"null", "https://127.0.0.1:8080", "http://evil.example", "http://127.0.0.1:8081"})
    EXPECT_FALSE(is_own_origin(origin, 8080)) << origin;
}

}  // namespace
}  // namespace isopatch::view
