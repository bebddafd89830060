#pragma once
// The viewer's HTTP server (isopatch view): the page and three.js from disk, the mesh as GLB or PLY,
// and POST /api/mesh, which meshes through the library. Loopback only (127.0.0.1).
//
// Routes:
//   GET  /                         web/src/index.html, and every file of web/src/
//   GET  /three/build/...          node_modules/three/build/ (three.module.js, ...)
//   GET  /three/examples/jsm/...   node_modules/three/examples/jsm/ (OrbitControls, GLTFLoader, ...)
//   GET  /api/state                {"id": N, "summary": {...}} of the mesh shown now (id 0: none yet)
//   POST /api/mesh                 view_request.hpp's JSON -> 200 {"id", "summary"}; a bad request or
//                                  surface -> 400 error_json(); superseded by a newer POST -> 409
//   GET  /api/mesh/N.glb, N.ply    the mesh of id N while it is the one shown (else 404);
//                                  ?download=1 adds Content-Disposition: attachment
// Anything else is 404; a path that is not safe (static_files.hpp) is 404 too, whatever it names.

#include <filesystem>
#include <memory>
#include <string>

#include "view/view_mesh.hpp"
#include "view/view_request.hpp"

namespace isopatch::view {

struct ViewConfig {
  /// The folder holding src/ (the page) and node_modules/three/ (installed by npm ci).
  std::filesystem::path web_root;
  /// 0: any free port.
  int port = 0;
  RequestLimits limits;
};

/// The web root built in (the repository's web/), or $ISOPATCH_WEB_ROOT when set.
std::filesystem::path default_web_root();

class ViewServer {
 public:
  /// \throw IoError when web_root lacks src/index.html or node_modules/three/build/three.module.js
  ///        (then scripts/install-deps.sh has not run), naming what is missing.
  explicit ViewServer(ViewConfig config);
  ~ViewServer();  ///< stops the server and waits for its threads
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// Makes `mesh` the one shown, with the request that made it (for the page's form), as a new id.
  void show(ViewMesh mesh);
  /// Binds 127.0.0.1 (the configured port, or a free one) and serves on a thread of its own.
  /// \return the port. \throw IoError when the port cannot be bound.
  int start();
  /// Blocks until stop() (from another thread) or a failure of the listening socket.
  void wait();
  /// Stops serving: cancels a run in progress; idempotent.
  void stop();
  /// "http://127.0.0.1:PORT/" once started.
  std::string url() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace isopatch::view
