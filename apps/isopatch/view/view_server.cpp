// ViewServer (view_server.hpp) on cpp-httplib (Debian's libcpp-httplib): routes, the one mesh shown,
// and the run in progress, cancelled when a newer request or stop() supersedes it.
#include "view/view_server.hpp"

#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/version.hpp>

#include <httplib.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <future>
#include <mutex>
#include <new>
#include <sstream>
#include <thread>

#include "view/static_files.hpp"

namespace isopatch::view {
namespace {

using nlohmann::json;

constexpr int kAcceptQueue = 256;  // connections the kernel holds before the server accepts them

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(body.dump(), "application/json");
}

std::string read_whole(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  std::string bytes(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)), '\0');
  in.seekg(0);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

}  // namespace

std::filesystem::path default_web_root() {
  if (const char* root = std::getenv("ISOPATCH_WEB_ROOT"); root != nullptr && *root != '\0') return root;
  return ISOPATCH_WEB_DIR;
}

struct ViewServer::Impl {
  ViewConfig config;
  std::vector<Mount> mounts;
  httplib::Server server;
  socket_t listening_socket = INVALID_SOCKET;  // recorded by the socket options callback
  std::thread listener;
  std::shared_future<void> listening_done;
  std::mutex join_mutex;
  int port = -1;

  void join_listener() {
    if (listening_done.valid()) listening_done.wait();
    const std::lock_guard lock(join_mutex);
    if (listener.joinable()) listener.join();
  }

  std::mutex state_mutex;  // guards the fields below
  std::shared_ptr<const ViewMesh> shown;
  std::uint64_t shown_id = 0;
  std::shared_ptr<std::atomic<bool>> running_cancel;  // of the newest run
  bool stopping = false;

  std::mutex run_mutex;  // one run at a time

  std::uint64_t show(ViewMesh mesh) {
    const std::lock_guard lock(state_mutex);
    ++shown_id;
    mesh.summary["id"] = shown_id;
    shown = std::make_shared<const ViewMesh>(std::move(mesh));
    return shown_id;
  }

  std::pair<std::uint64_t, std::shared_ptr<const ViewMesh>> current() {
    const std::lock_guard lock(state_mutex);
    return {shown_id, shown};
  }

  void handle_mesh(const httplib::Request& req, httplib::Response& res) {
    MeshRequest request;
    try {
      request = parse_mesh_request(req.body, config.limits);
    } catch (const Error& e) {
      send_json(res, 400, error_json(e));
      return;
    }
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    {
      const std::lock_guard lock(state_mutex);
      if (running_cancel) running_cancel->store(true);  // the older run gives way
      running_cancel = cancel;
      if (stopping) cancel->store(true);
    }
    const std::lock_guard run(run_mutex);
    const json superseded = {{"error", "superseded by a newer request"}, {"kind", "cancelled"}};
    if (cancel->load()) return send_json(res, 409, superseded);
    try {
      ViewMesh mesh = mesh_request(request, cancel.get());
      if (cancel->load()) return send_json(res, 409, superseded);
      const json summary = mesh.summary;
      const std::uint64_t id = show(std::move(mesh));
      json body = {{"id", id}, {"summary", summary}};
      body["summary"]["id"] = id;
      send_json(res, 200, body);
    } catch (const Error& e) {
      if (cancel->load()) return send_json(res, 409, superseded);
      send_json(res, 400, error_json(e));
    } catch (const std::bad_alloc&) {
      send_json(res, 400, {{"error", "out of memory"}, {"kind", "limit"}});
    }
  }

  void handle_download(const httplib::Request& req, httplib::Response& res) {
    const std::string digits = req.matches[1];
    std::uint64_t id = 0;
    const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), id);
    const auto [shown_now, mesh] = current();
    if (ec != std::errc() || ptr != digits.data() + digits.size() || mesh == nullptr || id != shown_now) {
      send_json(res, 404, {{"error", "no such mesh (a newer one is shown)"}, {"kind", "io"}});
      return;
    }
    const bool glb = req.matches[2] == "glb";
    res.set_header("Cache-Control", "no-store");
    if (req.has_param("download"))
      res.set_header("Content-Disposition",
                     std::string("attachment; filename=\"isopatch.") + (glb ? "glb" : "ply") + "\"");
    if (glb)
      res.set_content(mesh->glb, "model/gltf-binary");
    else
      res.set_content(encode_mesh(mesh->mesh, MeshFormat::PlyBinary), "application/octet-stream");
  }

  void handle_static(const httplib::Request& req, httplib::Response& res) const {
    const std::optional<std::filesystem::path> file = resolve_static(mounts, req.path);
    if (!file) {
      res.status = 404;
      res.set_content("not found\n", "text/plain");
      return;
    }
    res.set_header("Cache-Control", "no-cache");
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_content(read_whole(*file), content_type_for(*file));
  }

  /// Answers 403 and returns true for a request under another host name, or a POST from another site's
  /// page (DNS rebinding, cross-site requests).
  bool refused(const httplib::Request& req, httplib::Response& res) const {
    if (!is_own_host(req.get_header_value("Host"), port)) {
      send_json(res, 403,
                {{"error", "the Host header must name this server (127.0.0.1:" + std::to_string(port) +
                               "): requests under another host name are refused"},
                 {"kind", "forbidden"}});
      return true;
    }
    if (req.method == "POST" && !is_own_origin(req.get_header_value("Origin"), port)) {
      send_json(
          res, 403,
          {{"error", "a page of another site cannot ask this viewer for meshes"}, {"kind", "forbidden"}});
      return true;
    }
    return false;
  }

  void routes() {
    // httplib's default also sets SO_REUSEPORT, which would let a second server (of any program of
    // this user) listen on the same port and take some of the connections: address reuse only.
    // The socket is kept so that start() can widen its accept queue.
    server.set_socket_options([this](socket_t sock) {
      const int yes = 1;
      ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
      listening_socket = sock;
    });
    server.set_payload_max_length(config.limits.max_request_bytes);
    // Only requests that name this server, and no POST from another site's page (view_request.hpp).
    // A request with a body is judged after httplib has read the body (in its route, or the POST
    // catch-all below): answered before, the body left unread made the kernel reset the connection on
    // close, sometimes before the client had read the answer, and httplib read the body as the next
    // request.
    server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (req.method == "POST") return httplib::Server::HandlerResponse::Unhandled;
      return refused(req, res) ? httplib::Server::HandlerResponse::Handled
                               : httplib::Server::HandlerResponse::Unhandled;
    });
    server.set_read_timeout(10, 0);
    server.set_write_timeout(30, 0);
    server.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
      const auto [id, mesh] = current();
      // The library's version: the page shows it, one version for the library, the package and the page.
      send_json(res, 200,
                {{"id", id},
                 {"summary", mesh ? mesh->summary : json::object()},
                 {"version", std::string(kVersion)}});
    });
    server.Post("/api/mesh", [this](const httplib::Request& req, httplib::Response& res) {
      if (!refused(req, res)) handle_mesh(req, res);
    });
    server.Post(".*", [this](const httplib::Request& req, httplib::Response& res) {
      if (!refused(req, res)) send_json(res, 404, {{"error", "no such request"}, {"kind", "io"}});
    });
    server.Get(R"(/api/mesh/(\d{1,20})\.(glb|ply))",
               [this](const httplib::Request& req, httplib::Response& res) { handle_download(req, res); });
    server.Get(".*",
               [this](const httplib::Request& req, httplib::Response& res) { handle_static(req, res); });
    server.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, const std::exception_ptr&) {
          send_json(res, 500, {{"error", "internal error"}, {"kind", "internal"}});
        });
  }
};

ViewServer::ViewServer(ViewConfig config) : impl_(std::make_unique<Impl>()) {
  namespace fs = std::filesystem;
  const fs::path& root = config.web_root;
  for (const fs::path& needed :
       {root / "src" / "index.html", root / "node_modules/three/build/three.module.js"}) {
    std::error_code ec;
    if (!fs::is_regular_file(needed, ec))
      throw IoError("the viewer's page is incomplete: '" + needed.string() +
                    "' is missing (scripts/install-deps.sh installs three.js into web/node_modules)");
  }
  impl_->mounts = {{"/", root / "src"},
                   {"/three/build/", root / "node_modules/three/build"},
                   {"/three/examples/jsm/", root / "node_modules/three/examples/jsm"}};
  impl_->config = std::move(config);
  impl_->routes();
}

ViewServer::~ViewServer() {
  stop();
}

void ViewServer::show(ViewMesh mesh) {
  impl_->show(std::move(mesh));
}

int ViewServer::start() {
  Impl& s = *impl_;
  const char* host = "127.0.0.1";  // loopback only, never every interface
  if (s.config.port == 0)
    s.port = s.server.bind_to_any_port(host);
  else
    s.port = s.server.bind_to_port(host, s.config.port) ? s.config.port : -1;
  if (s.port <= 0)
    throw IoError("cannot listen on 127.0.0.1:" + std::to_string(s.config.port) + " (is the port in use?)");
  // Debian's compiled httplib listens with a queue of 5 connections (CPPHTTPLIB_LISTEN_BACKLOG is read
  // inside the library, not from our build). Under load the queue overflowed hundreds of times a minute
  // (TcpExtListenOverflows) and now and then a connection was reset. Listening again on the bound
  // socket only changes its queue length.
  if (::listen(s.listening_socket, kAcceptQueue) != 0)
    throw IoError("cannot listen on 127.0.0.1:" + std::to_string(s.port) + " with a queue of " +
                  std::to_string(kAcceptQueue) + " connections");
  std::promise<void> done;
  s.listening_done = done.get_future().share();
  s.listener = std::thread([&s, done = std::move(done)]() mutable {
    s.server.listen_after_bind();
    done.set_value();
  });
  // stop() can only close a socket the server already listens on: wait until it does.
  while (!s.server.is_running() &&
         s.listening_done.wait_for(std::chrono::milliseconds(1)) != std::future_status::ready) {
  }
  return s.port;
}

void ViewServer::wait() {
  impl_->join_listener();
}

void ViewServer::stop() {
  Impl& s = *impl_;
  {
    const std::lock_guard lock(s.state_mutex);
    s.stopping = true;
    if (s.running_cancel) s.running_cancel->store(true);
  }
  s.server.stop();
  s.join_listener();
}

std::string ViewServer::url() const {
  return "http://127.0.0.1:" + std::to_string(impl_->port) + "/";
}

}  // namespace isopatch::view
