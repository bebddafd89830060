#pragma once
// Internal: one encoder and one decoder per file format. Encoders write to a ByteSink (a file in chunks,
// or memory) as they go; decoders read bytes in memory. `name` is the file name used in error
// messages. Decoders throw IoError; encoders assume a validated mesh.

#include <isopatch/mesh.hpp>
#include <isopatch/mesh_io.hpp>

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/byte_sink.hpp"

namespace isopatch::io {

void encode_obj(const Mesh& mesh, ByteSink& out);
Mesh decode_obj(std::string_view bytes, const std::string& name);

void encode_ply(const Mesh& mesh, bool binary, ByteSink& out);
/// Reads ASCII, binary little-endian and binary big-endian PLY (told apart by the header).
Mesh decode_ply(std::string_view bytes, const std::string& name);

void encode_off(const Mesh& mesh, ByteSink& out);
Mesh decode_off(std::string_view bytes, const std::string& name);

void encode_stl(const Mesh& mesh, ByteSink& out);
/// Reads binary STL, or ASCII STL when the file starts with "solid" and is not a binary file of
/// exactly the declared size.
Mesh decode_stl(std::string_view bytes, const std::string& name);

/// glTF 2.0 binary; `colours` (linear RGB, one per vertex, or empty) become COLOR_0. Throws InputError
/// for a mesh without triangles or a colour count that is not the vertex count. Holds 12 bytes per
/// vertex (the normals) besides the sink's chunk.
void encode_glb(const Mesh& mesh, const std::vector<Vec3>& colours, ByteSink& out);

/// 3MF (3MF core specification 1.2): one mesh object in millimetres, one build item, identifiers from
/// the content. Throws InputError for a mesh without triangles or more than 2^32 - 1 vertices or
/// triangles, IoError when compressing fails.
void encode_3mf(const Mesh& mesh, ByteSink& out);

/// Any format to `out`: the encoder of `format` (colours for glTF only). \throw as the encoders;
/// InputError for an invalid mesh.
void encode_to(const Mesh& mesh, MeshFormat format, const std::vector<Vec3>& vertex_colours, ByteSink& out);

}  // namespace isopatch::io
