#pragma once
// Small helpers shared by the subcommands: parameters, output checks, number formatting.

#include <isopatch/convex_region.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace isopatch::cli {

/// Parses "name=value" items into a map. \throw InputError for a malformed item or a repeated name.
std::map<std::string, double> parse_params(const std::vector<std::string>& items);

/// The surface of `--surface spec` for a mesh read from a file (analyze, render): in the box
/// `box_text` when given; else a catalogue surface in its own box, and a formula in the mesh's
/// bounding box grown by 1% of its diagonal on every side (so that a flat mesh still has a box).
/// \throw as resolve_surface and parse_box; InputError for a formula with an empty mesh and no box.
SurfacePtr resolve_surface_for_mesh(const std::string& spec, const std::string& box_text,
                                    const std::vector<std::string>& params, const Mesh& mesh);

/// Checks, before any work is done, that `path` has a known mesh extension and that its folder exists
/// and is writable. \throw IoError otherwise.
void check_output_path(const std::string& path);

/// Checks that the folder of `path` exists and is writable and that `path` is not a folder.
/// \throw IoError otherwise.
void check_writable_location(const std::string& path);

/// The planes of `--region TEXT`: "a,b,c,d;..." or @FILE with one plane a line (parse_region).
/// \throw InputError for malformed planes; IoError when the file cannot be read or exceeds 1 MiB.
ConvexRegion region_argument(const std::string& text);

/// "12345" -> "12,345" style grouping for counts in summaries.
std::string group_digits(unsigned long long n);

/// Bytes of memory a mesh vertex may take at the peak of a run, with room to spare (the clean-up of a
/// 1M-vertex mesh peaks at about 300 B per vertex; docs/performance.md).
inline constexpr std::size_t kBytesPerVertexBudget = 1000;

/// The default of --max-vertices: the machine's physical memory / kBytesPerVertexBudget (at least one
/// million; 50 million when the memory cannot be read).
std::size_t default_vertex_budget();

}  // namespace isopatch::cli
