#pragma once
// The target edge length at a point, shared by the projection mesher (cell sizes, segments per side)
// and the remesher (split and collapse thresholds): a fixed length, or the smallest of a curvature size
// for a chordal error bound and a caller's size field, clamped to [smallest, largest].

#include <isopatch/stage_settings.hpp>
#include <isopatch/surface.hpp>

#include <functional>
#include <optional>

namespace isopatch {

struct SizeSpec {
  double largest = 0.0;                     ///< the size where nothing asks for less (the edge length)
  double smallest = 0.0;                    ///< the floor of a varying size
  std::optional<double> max_error;          ///< curvature sizes (size_for_error)
  std::function<double(const Vec3&)> user;  ///< a caller's size field
  bool varies() const { return max_error.has_value() || static_cast<bool>(user); }
};

/// The sizes `s` asks for over `box`: largest = default_edge_length(s, box); smallest = 1/2048 of
/// the longest box side (at most largest); max_error and size_field as given.
SizeSpec size_spec(const SizeSettings& s, const Box& box);

/// The target size at p. \throw InputError when the caller's size field gives a value that is not
/// positive and finite.
double target_size(const Surface& surface, const SizeSpec& spec, const Vec3& p);

}  // namespace isopatch
