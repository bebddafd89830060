#pragma once
/// \file mesh_io.hpp
/// Reading and writing meshes: OBJ, PLY (ASCII and binary little-endian, with per-vertex float
/// attributes), OFF and binary STL. The format is chosen by the file extension (case-insensitive).
///
/// Readers never trust a header: counts are checked against what the file can actually hold before
/// anything is allocated, indices are range-checked, and any malformed or truncated input throws an
/// IoError whose one-line message names the file and the problem. STL has no shared vertices: the
/// reader merges vertices with bit-identical coordinates (the writer's own output round-trips exactly).

#include <isopatch/mesh.hpp>

#include <string>

namespace isopatch {

enum class MeshFormat { Obj, PlyAscii, PlyBinary, Off, Stl };

/// The format for a path from its extension (.obj, .ply -> binary PLY, .off, .stl).
/// \throw IoError for an unknown extension.
MeshFormat format_from_path(const std::string& path);

/// Writes `mesh` to `path` in `format`. Positions are written in double precision where the format
/// allows (OBJ, OFF, PLY), float in STL. Attributes are written in PLY only.
/// \throw IoError if the file cannot be written; InputError if mesh.validate() fails.
void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format);
/// Same, with the format from the extension.
void write_mesh(const Mesh& mesh, const std::string& path);

/// Reads a mesh; polygons with more than 3 vertices are fan-triangulated.
/// \throw IoError for an unreadable, malformed, truncated or lying file.
Mesh read_mesh(const std::string& path, MeshFormat format);
/// Same, with the format from the extension (.ply detects ASCII or binary from the header).
Mesh read_mesh(const std::string& path);

}  // namespace isopatch
