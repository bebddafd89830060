// 3MF (3D Manufacturing Format, 3MF Consortium core specification 1.2): the package slicers and
// printers read, written through Debian's lib3mf (1.8, its C interface). One mesh object holding the
// whole mesh (float positions in millimetres, triangles as given: counter-clockwise seen from
// outside, as 3MF asks), one build item without a transform, and the producing application in the
// package's metadata, with identifiers made from the content (the same bytes every time). lib3mf
// writes coordinates with six decimals: a nanometre in millimetres, so a model should be in millimetres
// (or at least not far smaller). 3MF is written only; reading it is left to the tools that print.
#include "mesh/mesh_formats.hpp"

#include <isopatch/error.hpp>

#include <Model/COM/NMR_DLLInterfaces.h>

#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace isopatch::io {
namespace {

/// One lib3mf object, released when it goes.
class Lib3mfHandle {
 public:
  Lib3mfHandle() = default;
  ~Lib3mfHandle() {
    if (handle_ != nullptr) NMR::lib3mf_release(handle_);
  }
  Lib3mfHandle(const Lib3mfHandle&) = delete;
  Lib3mfHandle& operator=(const Lib3mfHandle&) = delete;
  NMR::PLib3MFBase** out() { return &handle_; }
  NMR::PLib3MFBase* get() const { return handle_; }

 private:
  NMR::PLib3MFBase* handle_ = nullptr;
};

/// Turns a lib3mf failure into an IoError naming the step and lib3mf's own message.
void check(LIB3MFRESULT result, NMR::PLib3MFBase* on, const char* step) {
  if (result == LIB3MF_OK) return;
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (on != nullptr) NMR::lib3mf_getlasterror(on, &code, &message);
  throw IoError(std::string("3MF: ") + step + " failed" +
                (message != nullptr && *message != '\0' ? std::string(": ") + message : std::string()));
}

/// A name-based UUID (RFC 4122 layout, version 5 bits) from the mesh's content and a salt: the same
/// mesh gets the same identifiers, so the package is the same bytes every time (lib3mf would draw
/// random ones), and different meshes get different ones.
std::string content_uuid(const Mesh& mesh, std::uint64_t salt) {
  std::uint64_t h[2] = {0xcbf29ce484222325ull ^ salt, 0x84222325cbf29ce4ull + salt};
  const auto mix = [&](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      h[0] = (h[0] ^ p[i]) * 0x100000001b3ull;
      h[1] = (h[1] ^ p[i]) * 0x100000001b3ull + (h[1] >> 29);
    }
  };
  mix(mesh.positions.data(), mesh.positions.size() * sizeof(Vec3));
  mix(mesh.triangles.data(), mesh.triangles.size() * sizeof(Triangle));
  h[0] = (h[0] & ~(0xFull << 12)) | (0x5ull << 12);  // version 5 (name-based)
  h[1] = (h[1] & ~(0x3ull << 62)) | (0x2ull << 62);  // RFC 4122 variant
  char text[37];
  std::snprintf(text, sizeof text, "%08x-%04x-%04x-%04x-%012llx", static_cast<unsigned>(h[0] >> 32),
                static_cast<unsigned>((h[0] >> 16) & 0xFFFF), static_cast<unsigned>(h[0] & 0xFFFF),
                static_cast<unsigned>(h[1] >> 48), static_cast<unsigned long long>(h[1] & 0xFFFFFFFFFFFFull));
  return text;
}

}  // namespace

std::string encode_3mf(const Mesh& mesh) {
  if (mesh.triangles.empty()) throw InputError("3MF: a mesh without triangles cannot be written");
  constexpr std::size_t kLargest = std::numeric_limits<DWORD>::max();
  if (mesh.positions.size() > kLargest || mesh.triangles.size() > kLargest)
    throw InputError("3MF: more than 2^32 - 1 vertices or triangles (write .ply blocks instead)");
  Lib3mfHandle model;
  check(NMR::lib3mf_createmodel(model.out()), nullptr, "creating a model");
  check(NMR::lib3mf_model_setunit(model.get(), NMR::MODELUNIT_MILLIMETER), model.get(), "setting the unit");
  check(NMR::lib3mf_model_addmetadatautf8(model.get(), "Application", "isopatch"), model.get(),
        "adding metadata");
  Lib3mfHandle object;
  check(NMR::lib3mf_model_addmeshobject(model.get(), object.out()), model.get(), "adding a mesh object");
  check(NMR::lib3mf_object_setnameutf8(object.get(), "isopatch mesh"), object.get(), "naming the mesh");
  check(NMR::lib3mf_object_setuuidutf8(object.get(), content_uuid(mesh, 1).c_str()), object.get(),
        "identifying the mesh");
  std::vector<NMR::MODELMESHVERTEX> vertices(mesh.positions.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (int a = 0; a < 3; ++a) vertices[i].m_fPosition[a] = static_cast<float>(mesh.positions[i][a]);
  std::vector<NMR::MODELMESHTRIANGLE> triangles(mesh.triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) triangles[t].m_nIndices[k] = mesh.triangles[t][k];
  check(NMR::lib3mf_meshobject_setgeometry(object.get(), vertices.data(), static_cast<DWORD>(vertices.size()),
                                           triangles.data(), static_cast<DWORD>(triangles.size())),
        object.get(), "setting the geometry");
  Lib3mfHandle item;
  check(NMR::lib3mf_model_addbuilditem(model.get(), object.get(), nullptr, item.out()), model.get(),
        "adding a build item");
  check(NMR::lib3mf_builditem_setuuidutf8(item.get(), content_uuid(mesh, 2).c_str()), item.get(),
        "identifying the build item");
  check(NMR::lib3mf_model_setbuilduuidutf8(model.get(), content_uuid(mesh, 3).c_str()), model.get(),
        "identifying the build");
  Lib3mfHandle writer;
  check(NMR::lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model.get(), "making a writer");
  ULONG64 size = 0;
  check(NMR::lib3mf_writer_getstreamsize(writer.get(), &size), writer.get(), "sizing the package");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  check(NMR::lib3mf_writer_writetobuffer(writer.get(), reinterpret_cast<BYTE*>(bytes.data()), size),
        writer.get(), "writing the package");
  return bytes;
}

}  // namespace isopatch::io
