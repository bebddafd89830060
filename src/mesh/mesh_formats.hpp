#pragma once
// Internal: one encoder and one decoder per file format, working on bytes in memory. `name` is the
// file name used in error messages. Decoders throw IoError; encoders assume a validated mesh.

#include <isopatch/mesh.hpp>

#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch::io {

std::string encode_obj(const Mesh& mesh);
Mesh decode_obj(std::string_view bytes, const std::string& name);

std::string encode_ply(const Mesh& mesh, bool binary);
/// Reads ASCII, binary little-endian and binary big-endian PLY (told apart by the header).
Mesh decode_ply(std::string_view bytes, const std::string& name);

std::string encode_off(const Mesh& mesh);
Mesh decode_off(std::string_view bytes, const std::string& name);

std::string encode_stl(const Mesh& mesh);
/// Reads binary STL, or ASCII STL when the file starts with "solid" and is not a binary file of
/// exactly the declared size.
Mesh decode_stl(std::string_view bytes, const std::string& name);

/// glTF 2.0 binary; `colours` (linear RGB, one per vertex, or empty) become COLOR_0. Throws InputError
/// for a mesh without triangles or a colour count that is not the vertex count.
std::string encode_glb(const Mesh& mesh, const std::vector<Vec3>& colours);

/// 3MF (3MF core specification 1.2) through lib3mf: one mesh object in millimetres, one build item,
/// identifiers from the content. Throws InputError for a mesh without triangles or more than 2^32 - 1
/// vertices or triangles, IoError when lib3mf fails.
std::string encode_3mf(const Mesh& mesh);

}  // namespace isopatch::io
