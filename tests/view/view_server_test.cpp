// The viewer's server on a free loopback port, spoken to over HTTP: pages, downloads, re-meshing,
// errors as JSON, hostile requests (path traversal, huge bodies, bad JSON, absurd sizes), superseding.
// Eigen (through the library's headers) before httplib.h: glibc's <resolv.h>, which httplib.h
// includes, defines a macro `_res` that breaks Eigen's headers.
#include "view/view_server.hpp"
#include "../mesh/mesh_fixtures.hpp"

#include <isopatch/error.hpp>
#include <isopatch/version.hpp>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <future>

namespace isopatch::view {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A web root with the two files the server insists on, and a file beside it that must stay unseen.
struct WebRoot {
  test::TempDir dir;
  fs::path root = dir.path() / "web";
  WebRoot() {
    fs::create_directories(root / "src");
    fs::create_directories(root / "node_modules/three/build");
    std::ofstream(root / "src/index.html") << "<!doctype html><title>isopatch view</title>";
    std::ofstream(root / "node_modules/three/build/three.module.js") << "export const REVISION = 'test';";
    std::ofstream(root / "node_modules/three/package.json") << R"({"name": "three"})";
    std::ofstream(dir.path() / "secret.txt") << "secret";
  }
};

// The raw answer to one request (its Host, Origin and JSON body as given), so that no client
// normalizes the path or the headers.
std::string raw_request(int port, const std::string& method, const std::string& target,
                        const std::string& host, const std::string& origin = {},
                        const std::string& body = {}) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  EXPECT_EQ(::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  std::string request = method + " " + target + " HTTP/1.1\r\n";
  if (!host.empty()) request += "Host: " + host + "\r\n";
  if (!origin.empty()) request += "Origin: " + origin + "\r\n";
  if (!body.empty())
    request += "Content-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) + "\r\n";
  request += "Connection: close\r\n\r\n" + body;
  EXPECT_EQ(::send(s, request.data(), request.size(), 0), static_cast<ssize_t>(request.size()));
  std::string answer;
  char buffer[4096];
  for (ssize_t n; (n = ::recv(s, buffer, sizeof buffer, 0)) > 0;)
    answer.append(buffer, static_cast<std::size_t>(n));
  ::close(s);
  return answer;
}

std::string raw_get(int port, const std::string& target) {
  return raw_request(port, "GET", target, "127.0.0.1:" + std::to_string(port));
}

// The status line of a raw request.
std::string raw_status(int port, const std::string& method, const std::string& target,
                       const std::string& host, const std::string& origin = {},
                       const std::string& body = {}) {
  const std::string answer = raw_request(port, method, target, host, origin, body);
  return answer.substr(0, answer.find("\r\n"));
}

class ViewServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ViewConfig config;
    config.web_root = web.root;
    config.limits.max_vertices = 30000;
    config.limits.time_limit = 20.0;
    server = std::make_unique<ViewServer>(config);
    server->show(view_mesh_file(test::octahedron(), "octahedron.off", nullptr));
    port = server->start();
    client = std::make_unique<httplib::Client>("127.0.0.1", port);
    client->set_read_timeout(60, 0);
  }

  json post(const json& body, int expected_status) {
    const auto r = client->Post("/api/mesh", body.dump(), "application/json");
    EXPECT_TRUE(r);
    if (!r) return {};
    EXPECT_EQ(r->status, expected_status) << r->body;
    return json::parse(r->body);
  }

  WebRoot web;
  std::unique_ptr<ViewServer> server;
  int port = 0;
  std::unique_ptr<httplib::Client> client;
};

TEST_F(ViewServerTest, ServesThePageAndThreeOnLoopback) {
  EXPECT_EQ(server->url(), "http://127.0.0.1:" + std::to_string(port) + "/");
  auto r = client->Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->body.find("isopatch view"), std::string::npos);
  EXPECT_EQ(r->get_header_value("Content-Type"), "text/html; charset=utf-8");
  r = client->Get("/three/build/three.module.js");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->get_header_value("Content-Type"), "text/javascript; charset=utf-8");
  r = client->Get("/missing.js");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 404);
}

TEST_F(ViewServerTest, RefusesPathsOutsideWhatItServes) {
  EXPECT_EQ(raw_get(port, "/").rfind("HTTP/1.1 200", 0), 0u);
  for (const char* target :
       {"/../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E%2Fsecret.txt", "/three/build/../../package.json",
        "/three/build/..%2f..%2fpackage.json", "/..\\secret.txt", "//etc/passwd", "/three/package.json",
        "/node_modules/three/package.json", "/src/index.html/.."}) {
    const std::string answer = raw_get(port, target);
    EXPECT_TRUE(answer.rfind("HTTP/1.1 404", 0) == 0 || answer.rfind("HTTP/1.1 400", 0) == 0)
        << target << ": " << answer;
    EXPECT_EQ(answer.find("secret"), std::string::npos) << target;
    EXPECT_EQ(answer.find("\"three\""), std::string::npos) << target;
  }
}

TEST_F(ViewServerTest, RefusesOtherHostNamesAndOtherSitesPosts) {
  const std::string own = "127.0.0.1:" + std::to_string(port);
  EXPECT_EQ(raw_status(port, "GET", "/", own), "HTTP/1.1 200 OK");
  EXPECT_EQ(raw_status(port, "GET", "/api/state", "LocalHost:" + std::to_string(port)), "HTTP/1.1 200 OK");
  EXPECT_EQ(raw_status(port, "GET", "/", "[::1]:" + std::to_string(port)), "HTTP/1.1 200 OK");
  // DNS rebinding: another site's name resolving to 127.0.0.1; the right names on another port; none.
  EXPECT_EQ(raw_status(port, "GET", "/", "attacker.example:" + std::to_string(port)),
            "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "GET", "/api/state", "127.0.0.1"), "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "GET", "/api/state", "127.0.0.1:" + std::to_string(port + 1)),
            "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "GET", "/", ""), "HTTP/1.1 403 Forbidden");
  // A POST from another site's page (the browser sends its Origin) is refused; the page's own is not.
  const std::string body = R"({"surface": "sphere", "edge_length": 0.3})";
  EXPECT_EQ(raw_status(port, "POST", "/api/mesh", own, "http://attacker.example", body),
            "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "POST", "/api/mesh", own, "null", body), "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "POST", "/api/mesh", own, "http://" + own, body), "HTTP/1.1 200 OK");
  // A POST is judged after its body is read (answered before, the unread body could reset the
  // connection under the answer): under another host name, and to a path the viewer does not serve.
  EXPECT_EQ(raw_status(port, "POST", "/api/mesh", "attacker.example:" + std::to_string(port), "", body),
            "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "POST", "/elsewhere", "attacker.example:" + std::to_string(port), "", body),
            "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(raw_status(port, "POST", "/elsewhere", own, "http://" + own, body), "HTTP/1.1 404 Not Found");
}

TEST_F(ViewServerTest, ShowsAMeshFileAndDownloadsIt) {
  auto r = client->Get("/api/state");
  ASSERT_TRUE(r);
  const json state = json::parse(r->body);
  EXPECT_EQ(state["id"], 1);
  EXPECT_EQ(state["version"], std::string(kVersion));
  EXPECT_EQ(state["summary"]["vertices"], 6);
  EXPECT_EQ(state["summary"]["triangles"], 8);
  EXPECT_EQ(state["summary"]["valence_6"], 0.0) << "every octahedron vertex has valence 4";
  EXPECT_NEAR(state["summary"]["min_angle"].get<double>(), 60.0, 1e-9);
  r = client->Get("/api/mesh/1.glb");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->body.substr(0, 4), "glTF");
  EXPECT_EQ(r->get_header_value("Content-Type"), "model/gltf-binary");
  r = client->Get("/api/mesh/1.ply?download=1");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->body.substr(0, 3), "ply");
  EXPECT_NE(r->get_header_value("Content-Disposition").find("attachment"), std::string::npos);
  for (const char* missing : {"/api/mesh/2.glb", "/api/mesh/0.ply", "/api/mesh/99999999999999999999.glb"}) {
    r = client->Get(missing);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 404) << missing;
  }
}

TEST_F(ViewServerTest, RemeshesAFormula) {
  const json answer = post({{"surface", "x^2 + y^2 + z^2 - 1"},
                            {"box", {-1.2, -1.2, -1.2, 1.2, 1.2, 1.2}},
                            {"edge_length", 0.2},
                            {"threads", 1}},
                           200);
  EXPECT_EQ(answer["id"], 2);
  const json& s = answer["summary"];
  EXPECT_GT(s["vertices"].get<int>(), 100);
  EXPECT_EQ(s["quality"], "preview");
  EXPECT_GT(s["valence_6"].get<double>(), 0.5);
  EXPECT_GT(s["min_angle"].get<double>(), 10.0);
  EXPECT_GE(s["seconds"].get<double>(), 0.0);
  for (const char* field : {"mean_curvature", "mean_curvature_exact", "gaussian_curvature", "distance"})
    EXPECT_NE(std::find(s["fields"].begin(), s["fields"].end(), field), s["fields"].end()) << field;
  auto r = client->Get("/api/mesh/1.glb");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 404) << "the old mesh is gone";
  r = client->Get("/api/mesh/2.glb");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST_F(ViewServerTest, BadRequestsAreJsonErrors) {
  json e = post({{"surface", "x^2 + * y"}, {"box", {-1, -1, -1, 1, 1, 1}}}, 400);
  EXPECT_EQ(e["kind"], "parse");
  EXPECT_EQ(e["line"], 1);
  EXPECT_EQ(e["column"], 7);
  e = post({{"surface", "tours"}}, 400);
  EXPECT_EQ(e["kind"], "unknown_surface");
  EXPECT_NE(e["error"].get<std::string>().find("torus"), std::string::npos) << "suggests the closest name";
  e = post({{"surface", "x^2 + y^2 + z^2 - 1"}}, 400);
  EXPECT_EQ(e["setting"], "box");
  e = post({{"surface", "x^2 + y^2 + z^2 - 1"}, {"box", {5, 5, 5, 6, 6, 6}}}, 400);
  EXPECT_EQ(e["kind"], "no_surface");
  e = post({{"surface", "torus"}, {"edge_length", "tiny"}}, 400);
  EXPECT_EQ(e["setting"], "edge_length");

  auto r = client->Post("/api/mesh", "{\"surface\": ", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(json::parse(r->body)["setting"], "request");
  r = client->Post("/api/mesh", std::string(200 * 1024, ' '), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413) << "a body beyond the limit is refused before it is read";
  r = client->Get("/api/state");
  ASSERT_TRUE(r);
  EXPECT_EQ(json::parse(r->body)["id"], 1) << "errors leave the mesh shown alone";
}

TEST_F(ViewServerTest, AbsurdSizesRunIntoTheBudget) {
  const auto start = std::chrono::steady_clock::now();
  const json e = post({{"surface", "torus"}, {"edge_length", 1e-9}, {"time_limit", 3}}, 400);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(e["kind"], "limit") << e.dump();
  EXPECT_LT(seconds, 15.0);
  auto r = client->Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << "the server lives on";
}

TEST(ViewServer, ANewerRequestSupersedesARunningOne) {
  // A budget the first run cannot exhaust soon (the torus at edge length 0.004 has about 2 million
  // vertices), so that only the second request can end it.
  const WebRoot web;
  ViewConfig config;
  config.web_root = web.root;
  config.limits.max_vertices = 10000000;
  config.limits.time_limit = 120.0;
  ViewServer server(config);
  const int port = server.start();
  auto slow = std::async(std::launch::async, [port] {
    httplib::Client other("127.0.0.1", port);
    other.set_read_timeout(120, 0);
    const auto r =
        other.Post("/api/mesh", json({{"surface", "torus"}, {"edge_length", 0.004}, {"threads", 1}}).dump(),
                   "application/json");
    return r ? r->status : -1;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  httplib::Client client("127.0.0.1", port);
  client.set_read_timeout(120, 0);
  const auto start = std::chrono::steady_clock::now();
  const auto r =
      client.Post("/api/mesh", json({{"surface", "sphere"}, {"edge_length", 0.3}, {"threads", 1}}).dump(),
                  "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(slow.get(), 409);
  EXPECT_EQ(json::parse(r->body)["summary"]["name"], "sphere");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0)
      << "the first run stops soon after it is superseded";
}

TEST(ViewServer, RefusesABusyPortAndAnIncompleteWebRoot) {
  const WebRoot web;
  ViewConfig config;
  config.web_root = web.root;
  ViewServer first(config);
  config.port = first.start();
  ViewServer second(config);
  EXPECT_THROW(second.start(), IoError);
  first.stop();
  first.stop();  // idempotent
  config.web_root = web.dir.path() / "nothing";
  EXPECT_THROW(ViewServer{config}, IoError);
}

}  // namespace
}  // namespace isopatch::view
