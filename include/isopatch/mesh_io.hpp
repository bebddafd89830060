#pragma once
/// \file mesh_io.hpp
/// Reading and writing meshes: OBJ, PLY (ASCII and binary, with per-vertex float attributes), OFF and
/// STL. The format is chosen by the file extension (case-insensitive).
///
/// Writers: positions in double precision as the shortest decimal that reads back to the same double
/// (OBJ, OFF, ASCII PLY; exact like %.17g, but shorter) or as raw doubles (binary little-endian PLY),
/// as floats in binary STL. Attributes are written in PLY only, one `property float` each.
///
/// Readers: OBJ keeps `v` and `f` (corners `a`, `a/b`, `a//c`, `a/b/c`; negative = relative; a face
/// may refer only to vertices defined before it) and skips the other statements of the OBJ
/// specification. PLY (Turk 1994) is ASCII, binary_little_endian or binary_big_endian, elements in any
/// order, scalars of any PLY type; vertex x, y, z are required, every other scalar vertex property
/// becomes an attribute, vertex list properties and unknown elements are skipped; faces come from the
/// list `vertex_indices` (or `vertex_index`). OFF is Geomview's, with '#' comments. STL is binary, or
/// ASCII when the file starts with "solid" and is not a binary file of the declared size; corners with
/// bit-identical float coordinates are merged, so a closed mesh is indexed (and closed) again.
/// Polygons are fan-triangulated.
///
/// Readers never trust a header: counts are checked against what the file can actually hold before
/// anything is allocated, indices are range-checked, and any malformed or truncated input (bad or
/// non-finite coordinates, faces with fewer than 3 or more than 1000 vertices, degenerate triangles,
/// data after the declared items, ...) throws an IoError whose one-line message names the file and
/// the problem. The mesh returned always passes Mesh::validate().

#include <isopatch/mesh.hpp>

#include <string>
#include <string_view>

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

/// The bytes write_mesh would write (for in-memory use, tests and fuzzing).
/// \throw InputError if mesh.validate() fails.
std::string encode_mesh(const Mesh& mesh, MeshFormat format);
/// Parses bytes as read_mesh would parse a file; `name` stands for the file in error messages.
/// PlyAscii and PlyBinary both accept any PLY encoding (ASCII, binary little- or big-endian).
/// \throw IoError for malformed, truncated or lying bytes.
Mesh decode_mesh(std::string_view bytes, MeshFormat format, const std::string& name = "<memory>");

}  // namespace isopatch
