// libFuzzer target: the mesh readers. The first byte picks the format (modulo 5: OBJ, ASCII PLY,
// binary PLY, OFF, STL), the rest is the file. decode_mesh must return a mesh that passes
// Mesh::validate() or throw IoError with a one-line message naming the file; a decoded mesh must
// encode and decode again (except STL, whose floats may merge corners).
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

constexpr isopatch::MeshFormat kFormats[] = {isopatch::MeshFormat::Obj, isopatch::MeshFormat::PlyAscii,
                                             isopatch::MeshFormat::PlyBinary, isopatch::MeshFormat::Off,
                                             isopatch::MeshFormat::Stl};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const isopatch::MeshFormat format = kFormats[data[0] % 5];
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const isopatch::Mesh mesh = isopatch::decode_mesh(bytes, format, "fuzz.input");
    mesh.validate();
    if (format == isopatch::MeshFormat::Stl) return 0;  // floats: rounding may merge corners again
    const std::string again = isopatch::encode_mesh(mesh, format);
    const isopatch::Mesh back = isopatch::decode_mesh(again, format, "fuzz.again");
    check(back.triangle_count() == mesh.triangle_count());
  } catch (const isopatch::IoError& e) {
    const std::string message = e.what();
    check(message.rfind("fuzz.input", 0) == 0 && message.find('\n') == std::string::npos);
  }
  return 0;
}
