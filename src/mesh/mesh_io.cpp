// Public entry points of mesh I/O: the format from the extension, then one encoder or decoder per
// format (obj_io.cpp, ply_io.cpp, off_io.cpp, stl_io.cpp; glb_io.cpp and threemf_io.cpp write only). Files
// are read whole, and written in chunks as the encoders make them (byte_sink.hpp).
#include <isopatch/mesh_io.hpp>

#include "mesh/io_util.hpp"
#include "mesh/mesh_formats.hpp"

#include <cctype>
#include <filesystem>

namespace isopatch {

MeshFormat format_from_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::PlyBinary;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".glb") return MeshFormat::Glb;
  if (ext == ".3mf") return MeshFormat::ThreeMf;
  throw IoError(path + ": unknown mesh file extension '" + ext +
                "' (use .obj, .ply, .off, .stl, .glb or .3mf)");
}

void io::encode_to(const Mesh& mesh, MeshFormat format, const std::vector<Vec3>& vertex_colours,
                   io::ByteSink& out) {
  mesh.validate();
  switch (format) {
    case MeshFormat::Obj:
      return io::encode_obj(mesh, out);
    case MeshFormat::PlyAscii:
      return io::encode_ply(mesh, false, out);
    case MeshFormat::PlyBinary:
      return io::encode_ply(mesh, true, out);
    case MeshFormat::Off:
      return io::encode_off(mesh, out);
    case MeshFormat::Stl:
      return io::encode_stl(mesh, out);
    case MeshFormat::Glb:
      return io::encode_glb(mesh, vertex_colours, out);
    case MeshFormat::ThreeMf:
      return io::encode_3mf(mesh, out);
  }
  throw InputError("unknown mesh format");
}

std::string encode_mesh(const Mesh& mesh, MeshFormat format, const std::vector<Vec3>& vertex_colours) {
  std::string bytes;
  io::ByteSink out(bytes);
  io::encode_to(mesh, format, vertex_colours, out);
  return bytes;
}

Mesh decode_mesh(std::string_view bytes, MeshFormat format, const std::string& name) {
  switch (format) {
    case MeshFormat::Obj:
      return io::decode_obj(bytes, name);
    case MeshFormat::PlyAscii:
    case MeshFormat::PlyBinary:
      return io::decode_ply(bytes, name);
    case MeshFormat::Off:
      return io::decode_off(bytes, name);
    case MeshFormat::Stl:
      return io::decode_stl(bytes, name);
    case MeshFormat::Glb:
      throw IoError(name +
                    ": reading glTF is not supported (isopatch writes .glb; read .ply, .obj, .off "
                    "or .stl)");
    case MeshFormat::ThreeMf:
      throw IoError(name +
                    ": reading 3MF is not supported (isopatch writes .3mf for printing; read .ply, .obj, "
                    ".off or .stl)");
  }
  throw InputError("unknown mesh format");
}

void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format,
                const std::vector<Vec3>& vertex_colours, const std::atomic<bool>* cancel) {
  mesh.validate();  // before the file is made
  io::write_file(
      path, [&](io::ByteSink& out) { io::encode_to(mesh, format, vertex_colours, out); }, cancel);
}

void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format,
                const std::vector<Vec3>& vertex_colours) {
  write_mesh(mesh, path, format, vertex_colours, nullptr);
}

void write_mesh(const Mesh& mesh, const std::string& path, const std::vector<Vec3>& vertex_colours) {
  write_mesh(mesh, path, format_from_path(path), vertex_colours);
}

void write_whole_file(const std::string& path, std::string_view bytes) {
  io::write_file(path, [bytes](io::ByteSink& out) { out += bytes; });
}

void remove_unfinished_files() noexcept {
  io::remove_unfinished();
}

Mesh read_mesh(const std::string& path, MeshFormat format) {
  return decode_mesh(io::load_file(path), format, path);
}

Mesh read_mesh(const std::string& path) {
  return read_mesh(path, format_from_path(path));
}

}  // namespace isopatch
