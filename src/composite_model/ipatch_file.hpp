#pragma once
/// \file ipatch_file.hpp
/// The .ipatch text format (docs/ipatch.md): a control polyhedron (level 1: a header line, then OBJ-like
/// `v` and `f` lines, optionally `vn`, `edge` and `face` lines), or a convex solid with setback vertex
/// blends (level 2: the same `v`/`f` lines or `solid box`, and a `blend` line), read into a Composite.

#include "composite_model/composite.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace isopatch {

/// The largest .ipatch file read (bytes), and the most vertices and faces it may declare.
inline constexpr std::size_t kMaxIpatchBytes = 8u << 20;
inline constexpr std::size_t kMaxIpatchVertices = 20000;
inline constexpr std::size_t kMaxIpatchFaces = 20000;

/// Parses .ipatch text and builds its composite (build_control_polyhedron or build_setback_solid).
/// \param source_name  names the text in errors ("box.ipatch")
/// \throw InputError "<source>:<line>:<column>: <what>" for malformed lines (unknown keywords, missing or
///        extra fields, numbers that are not finite or exceed 1e6 in size, indices out of range, counts
///        over the limits, a missing header, text over kMaxIpatchBytes), bad topology (the line of the
///        face or vertex to blame), and "<source>: <what>" for geometry the construction refuses.
Composite parse_ipatch(std::string_view text, std::string_view source_name);

/// Reads and parses a file. \throw IoError when it cannot be read or is larger than kMaxIpatchBytes;
/// InputError as parse_ipatch.
Composite read_ipatch(const std::string& path);

}  // namespace isopatch
