#pragma once
// The singular points of f = 0 (singular_points.hpp) as the tool reports them: searched in the region a
// run meshed, one warning line for `isopatch mesh`, a section of --stats-json and of `analyze --json`.

#include <isopatch/isopatch.hpp>
#include <isopatch/singular_points.hpp>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

namespace isopatch::cli {

/// A search and where it looked.
struct SingularRun {
  SingularPoints found;
  Box box;               ///< the box searched (the user's coordinates)
  double seconds = 0.0;  ///< wall time of the search
};

/// Searches `box` with the smallest boxes a quarter of `edge_length` (at least 1/1024 of the box's
/// longest side: a finer mesh does not make the search slower than that). With a frame, `box` and `region`
/// are in the frame's coordinates (as Settings says): the bounds of the rotated box are searched and the
/// points outside the rotated box or the region are dropped (components regrouped). `sampled`: the surface
/// interpolates a volume, whose mirror boundary makes the normal derivative vanish on every face of the box,
/// so that f = 0 meets a face where its tangential gradient vanishes in points with grad f = 0 that are no
/// feature of the data: points within 1e-6 of the box's size of a face are dropped. \throw as
/// find_singular_points.
SingularRun search_singular_points(const Surface& surface, const Box& box, double edge_length,
                                   const ConvexRegion& region = {}, const std::optional<Frame>& frame = {},
                                   bool sampled = false);

/// The run's box and edge length from the settings of `isopatch mesh` (its box or the surface's, the
/// default edge length of the settings) and the search in it.
SingularRun search_singular_points(const Surface& surface, const Settings& settings, bool sampled = false);

/// One "warning: ..." line when singular points were found ("warning: 2 singular points of f = 0 (grad f
/// = 0) in the box: (0, 0, -1), (0, 0, 1)"), or when the search stopped at its budget; nothing otherwise
/// (nor for a surface that could not be searched: --stats-json says so).
void print_singular_warning(const SingularRun& run, std::FILE* out);

/// {"status", "searched", "complete", "reason" (when not complete), "points" (isolated singular
/// points), "curves" (singular curves), "degenerate" (components where f = 0 is smooth and only grad f
/// vanishes, SingularComponent::smooth_sheet), "positions": [[x, y, z], ...] of the isolated points,
/// "curve_list" and "degenerate_list": [{"samples", "from", "to" (the bounds of the samples), "points"}],
/// "box", "min_box_size", "spacing", "boxes", "starts", "seconds"}.
nlohmann::ordered_json singular_json(const SingularRun& run);

}  // namespace isopatch::cli
