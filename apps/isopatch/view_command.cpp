// `isopatch view [MESH | SURFACE] [--port N]`: the live viewer (view/view_server.hpp). Prints the
// page's URL as its first line and serves until Ctrl-C (SIGINT) or SIGTERM.
#include <isopatch/mesh_io.hpp>

#include <pthread.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "cli_support.hpp"
#include "commands.hpp"
#include "view/view_mesh.hpp"
#include "view/view_server.hpp"

namespace isopatch::cli {
namespace {

struct ViewOptions {
  std::string input = "torus";
  std::string surface;
  std::string box;
  std::string quality = "preview";
  int port = 0;
  std::string web_root;
};

// A mesh file when `input` names an existing file with a mesh extension; else a surface.
bool is_mesh_file(const std::string& input) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(input, ec)) return false;
  try {
    format_from_path(input);
    return true;
  } catch (const IoError&) {
    return false;
  }
}

view::ViewMesh first_mesh(const ViewOptions& o) {
  if (is_mesh_file(o.input)) {
    Mesh mesh = read_mesh(o.input);
    SurfacePtr surface;
    if (!o.surface.empty()) surface = resolve_surface_for_mesh(o.surface, o.box, {}, mesh);
    return view::view_mesh_file(std::move(mesh), std::filesystem::path(o.input).filename().string(),
                                surface.get());
  }
  if (!o.surface.empty()) throw InputError("--surface goes with a mesh file (here the input is a surface)");
  view::MeshRequest request;  // from the command line: no server budget, as isopatch mesh
  request.surface = o.input;
  request.settings.quality = parse_quality(o.quality);
  if (!o.box.empty()) request.settings.box = parse_box(o.box);
  request.settings.validate();
  return view::mesh_request(request, nullptr);
}

int run_view(const ViewOptions& o) {
  // Signals go to one waiting thread, which stops the server; every other thread blocks them.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  view::ViewConfig config;
  config.web_root = o.web_root.empty() ? view::default_web_root() : std::filesystem::path(o.web_root);
  config.port = o.port;
  if (o.port < 0 || o.port > 65535) throw InputError("--port must be 0..65535 (0: a free port)", "port");
  view::ViewServer server(config);
  server.show(first_mesh(o));
  server.start();
  std::printf("%s\n", server.url().c_str());
  std::fflush(stdout);
  std::fprintf(stderr, "isopatch: serving the viewer on loopback only; Ctrl-C stops it\n");
  std::thread waiter([&server, signals] {
    int signal = 0;
    sigwait(&signals, &signal);
    server.stop();
  });
  server.wait();
  pthread_kill(waiter.native_handle(), SIGINT);  // wakes the waiter when the server ended on its own
  waiter.join();
  return 0;
}

}  // namespace

Runner add_view_command(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Live viewer in the browser: type a formula, see the mesh, its curvature and isophotes");
  cmd->add_option(
         "input", o->input,
         "A mesh file (.ply, .obj, .off, .stl), shown as it is, or a surface: catalogue name, formula")
      ->capture_default_str();
  cmd->add_option(
      "--surface", o->surface,
      "With a mesh file: the surface for exact curvature and distance (catalogue name or formula)");
  cmd->add_option("--box", o->box, "Box x0,y0,z0,x1,y1,z1 of a formula (a mesh file: default its bounds)");
  cmd->add_option("--quality", o->quality,
                  "preview | default | fine (of the first mesh; the page can change it)")
      ->capture_default_str();
  cmd->add_option("--port", o->port, "Port on 127.0.0.1 (0: a free one)")->capture_default_str();
  cmd->add_option(
      "--web-root", o->web_root,
      "Folder with src/ and node_modules/three/ (default: the repository's web/, or $ISOPATCH_WEB_ROOT)");
  return [o] { return run_view(*o); };
}

}  // namespace isopatch::cli
