#pragma once
/// \file orient.hpp
/// Orienting a peer's mesh the way isopatch does (kept apart from peer_support.hpp so that the files
/// instantiating CGAL include nothing more). Benchmark code only.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

namespace isopatch::bench {

/// Flips every triangle when most of the area faces against grad f, so that triangles are
/// counter-clockwise seen from outside (along grad f), as isopatch writes them.
void orient_along_gradient(Mesh& mesh, const Surface& surface);

}  // namespace isopatch::bench
