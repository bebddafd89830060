#pragma once
/// \file mesh_io.hpp
/// Reading and writing meshes: OBJ, PLY (ASCII and binary, with per-vertex float attributes), OFF and
/// STL; writing glTF 2.0 binary (.glb) and 3MF (.3mf). The format is chosen by the file extension
/// (case-insensitive).
///
/// Writers: positions in double precision as the shortest decimal that reads back to the same double
/// (OBJ, OFF, ASCII PLY; exact like %.17g, but shorter) or as raw doubles (binary little-endian PLY),
/// as floats in binary STL. Attributes are written in PLY, one `property float` each, and in glTF.
///
/// glTF 2.0 binary (Khronos glTF 2.0 specification; the container written by TinyGLTF): one mesh of
/// one indexed triangle primitive, float POSITION (with its bounds), unit area-weighted NORMAL,
/// uint32 indices, COLOR_0 (float linear RGB) when colours are given, and every vertex attribute as a
/// float application-specific attribute named `_` + its name in capitals (`mean_curvature` ->
/// `_MEAN_CURVATURE`); glTF forbids NaN and infinity, so a value that is not finite is stored as
/// kGlbUndefined. A double-sided, non-metallic white material shows COLOR_0 as it is. The node turns
/// the mesh from isopatch's z up to glTF's y up; positions stay as they are. Reading glTF is not
/// supported (IoError).
///
/// 3MF (3MF Consortium core specification 1.2, the package slicers read; written by Debian's lib3mf):
/// one mesh object holding the whole mesh, positions as floats in millimetres (lib3mf prints six
/// decimals: a nanometre), triangles as they are (counter-clockwise seen from outside, as 3MF asks), one
/// build item without a transform, identifiers derived from the content so the same mesh gives the same
/// bytes. Attributes and colours are not written. Reading 3MF is not supported (IoError).
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

#include <atomic>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch {

enum class MeshFormat { Obj, PlyAscii, PlyBinary, Off, Stl, Glb, ThreeMf };

/// What a glTF attribute holds where the mesh's value is NaN or infinite (the lowest float).
inline constexpr float kGlbUndefined = -std::numeric_limits<float>::max();

/// The format for a path from its extension (.obj, .ply -> binary PLY, .off, .stl, .glb, .3mf).
/// \throw IoError for an unknown extension.
MeshFormat format_from_path(const std::string& path);

/// Writes `mesh` to `path` in `format`, streamed in chunks and whole or not at all (write_whole_file).
/// Positions are written in double precision where the format allows (OBJ, OFF, PLY), float in STL and
/// glTF. Attributes are written in PLY and glTF only.
/// `vertex_colours` (linear RGB in [0, 1], one per vertex, or empty for none) are written in glTF only,
/// as COLOR_0 (render.hpp's field_vertex_colours() makes them from a field).
/// \throw IoError if the file cannot be written; InputError if mesh.validate() fails, or for glTF a
///        mesh without triangles or a colour count that is not the vertex count, or for 3MF a mesh
///        without triangles or with more than 2^32 - 1 vertices or triangles.
void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format,
                const std::vector<Vec3>& vertex_colours = {});
/// Same, stopped when `cancel` (may be null) becomes true while it writes: checked before each 1 MiB
/// chunk goes to the file and before the rename. A stopped write removes its temporary file, leaves a
/// file already at `path` as it was and throws LimitError("cancel") naming the file. For a caller that
/// writes on a worker thread and lets the user stop it (Python's Mesh.write and Ctrl-C).
void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format,
                const std::vector<Vec3>& vertex_colours, const std::atomic<bool>* cancel);
/// Same, with the format from the extension.
void write_mesh(const Mesh& mesh, const std::string& path, const std::vector<Vec3>& vertex_colours = {});

/// Writes `bytes` to `path` whole or not at all: into a temporary file beside `path` (beside the file a
/// symbolic link points to, which keeps pointing to it), which then replaces `path` in one rename. On
/// an error, and on a signal whose handler calls remove_unfinished_files(), the temporary file is
/// removed and a file already at `path` is left as it was. A path that exists and is not a regular file
/// (a device such as /dev/null, a pipe) is written directly. Every writer of the library and the tool
/// writes this way.
/// \throw IoError naming the file: a folder that is missing or not writable, a full disk, a failed
///        rename.
void write_whole_file(const std::string& path, std::string_view bytes);

/// Removes the temporary files of the writes in progress in this process (write_mesh,
/// write_whole_file). Async-signal-safe: for a SIGINT or SIGTERM handler, before the process ends.
void remove_unfinished_files() noexcept;

/// Reads a mesh; polygons with more than 3 vertices are fan-triangulated.
/// \throw IoError for an unreadable, malformed, truncated or lying file.
Mesh read_mesh(const std::string& path, MeshFormat format);
/// Same, with the format from the extension (.ply detects ASCII or binary from the header).
Mesh read_mesh(const std::string& path);

/// The bytes write_mesh would write (for in-memory use, tests and fuzzing).
/// \throw InputError as write_mesh.
std::string encode_mesh(const Mesh& mesh, MeshFormat format, const std::vector<Vec3>& vertex_colours = {});
/// Parses bytes as read_mesh would parse a file; `name` stands for the file in error messages.
/// PlyAscii and PlyBinary both accept any PLY encoding (ASCII, binary little- or big-endian).
/// \throw IoError for malformed, truncated or lying bytes, and for Glb and ThreeMf (not read).
Mesh decode_mesh(std::string_view bytes, MeshFormat format, const std::string& name = "<memory>");

}  // namespace isopatch
