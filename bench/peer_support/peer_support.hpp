#pragma once
/// \file peer_support.hpp
/// What the peer tools of bench/ (CGAL Surface_mesher, VTK Flying Edges, CGAL remeshing) share: the
/// surface arguments as `isopatch mesh` takes them, the output, and the steps of a surface peer
/// (orient.hpp orients a peer's mesh). Benchmark code only.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/surface.hpp>

#include <CLI/CLI.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace isopatch::bench {

/// "name=value" items -> map, as `isopatch mesh --param`.
/// \throw InputError for a malformed item or a name given twice
std::map<std::string, double> parse_params(const std::vector<std::string>& items);

/// The surface of a peer's command line: catalogue name, formula or @file, with --box and --param.
struct SurfaceArguments {
  std::string surface;
  std::string box;
  std::vector<std::string> params;

  /// Adds the positional `surface` (required), --box and --param to `app`; `this` must outlive it.
  void add_to(CLI::App& app);
  /// The surface these arguments name (resolve_surface). \throw as resolve_surface and parse_params
  SurfacePtr resolve() const;
};

/// The output of a peer's command line: the mesh file (-o, required) and --json (one JSON line
/// instead of a summary).
struct OutputArguments {
  std::string path;
  bool json = false;

  /// Adds -o/--output and --json to `app`; `this` must outlive it.
  void add_to(CLI::App& app);
  /// \throw IoError for an extension isopatch cannot write (before any work)
  void check() const;
};

/// The command line of a peer that meshes a surface: the surface, the output and its own options.
template <class Options>
struct SurfacePeerArguments {
  SurfaceArguments surface;
  OutputArguments output;
  Options options;

  /// Adds the surface's and the output's arguments to `app` (the peer adds its options).
  void add_to(CLI::App& app) {
    surface.add_to(app);
    output.add_to(app);
  }
};

/// The steps every surface peer takes: checks the output's extension, resolves the surface, runs
/// `mesher(surface)` (a result with a `mesh` member) and writes that mesh. Returns the surface and
/// the result, for the peer's summary. \throw whatever those steps throw
template <class Options, class Mesher>
auto mesh_and_write(const SurfacePeerArguments<Options>& a, Mesher&& mesher) {
  a.output.check();
  SurfacePtr surface = a.surface.resolve();
  auto result = std::forward<Mesher>(mesher)(*surface);
  write_mesh(result.mesh, a.output.path);
  return std::pair{std::move(surface), std::move(result)};
}

}  // namespace isopatch::bench
