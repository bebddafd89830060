#pragma once
/// \file peer_support.hpp
/// What the peer tools of bench/ (CGAL Surface_mesher, VTK Flying Edges, CGAL remeshing) share: the
/// surface arguments as `isopatch mesh` takes them, and orienting a peer's mesh the way isopatch does.
/// Benchmark code only.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <CLI/CLI.hpp>

#include <map>
#include <string>
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

/// Flips every triangle when most of the area faces against grad f, so that triangles are
/// counter-clockwise seen from outside (along grad f), as isopatch writes them.
void orient_along_gradient(Mesh& mesh, const Surface& surface);

}  // namespace isopatch::bench
