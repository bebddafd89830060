// 3MF (3D Manufacturing Format, 3MF Consortium core specification 1.2): the package slicers and
// printers read, written as it goes: an OPC package (a zip archive, zip_stream.hpp) with the content
// types, the package relationship and one model part holding one mesh object (float positions in
// millimetres printed with six decimals, a nanometre, as lib3mf prints them; triangles as given:
// counter-clockwise seen from outside, as 3MF asks), one build item without a transform, and the
// producing application in the model's metadata, with identifiers made from the content (the same
// bytes every time). The model's XML is compressed as it is printed, so writing holds a chunk, not the
// package. 3MF is written only; reading it is left to the tools that print.
#include "mesh/mesh_formats.hpp"

#include <isopatch/error.hpp>

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>

#include "mesh/byte_sink.hpp"
#include "mesh/zip_stream.hpp"

namespace isopatch::io {
namespace {

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

void encode_3mf(const Mesh& mesh, ByteSink& out) {
  if (mesh.triangles.empty()) throw InputError("3MF: a mesh without triangles cannot be written");
  constexpr std::size_t kLargest = std::numeric_limits<std::uint32_t>::max();
  if (mesh.positions.size() > kLargest || mesh.triangles.size() > kLargest)
    throw InputError("3MF: more than 2^32 - 1 vertices or triangles (write .ply blocks instead)");
  ZipStream zip(out);
  const auto part = [&zip](const std::string& name, const std::string& text) {
    zip.begin_entry(name);
    zip.write(text.data(), text.size());
    zip.end_entry();
  };
  zip.begin_entry("3D/3dmodel.model");
  {
    ByteSink xml([&zip](const char* data, std::size_t count) { zip.write(data, count); });
    xml += R"(<?xml version="1.0" encoding="utf-8"?>)"
           "\n"
           R"(<model xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02" unit="millimeter" )"
           R"(xml:lang="en-US" xmlns:p="http://schemas.microsoft.com/3dmanufacturing/production/2015/06">)"
           "\n"
           "\t<metadata name=\"Application\">isopatch</metadata>\n\t<resources>\n"
           "\t\t<object id=\"1\" name=\"isopatch mesh\" type=\"model\" p:UUID=\"";
    xml += content_uuid(mesh, 1);
    xml += "\">\n\t\t\t<mesh>\n\t\t\t\t<vertices>\n";
    char number[64];
    const auto coordinate = [&](const char* label, double value) {
      xml += label;
      // The float position, with six decimals ("%f" of a float's value).
      const auto result =
          std::to_chars(number, number + sizeof number, static_cast<double>(static_cast<float>(value)),
                        std::chars_format::fixed, 6);
      xml.append(number, result.ptr);
      xml += '"';
    };
    for (const Vec3& p : mesh.positions) {
      coordinate("\t\t\t\t\t<vertex x=\"", p.x());
      coordinate(" y=\"", p.y());
      coordinate(" z=\"", p.z());
      xml += " />\n";
    }
    xml += "\t\t\t\t</vertices>\n\t\t\t\t<triangles>\n";
    const auto index = [&](const char* label, std::uint32_t v) {
      xml += label;
      const auto result = std::to_chars(number, number + sizeof number, v);
      xml.append(number, result.ptr);
      xml += '"';
    };
    for (const Triangle& t : mesh.triangles) {
      index("\t\t\t\t\t<triangle v1=\"", t[0]);
      index(" v2=\"", t[1]);
      index(" v3=\"", t[2]);
      xml += " />\n";
    }
    xml += "\t\t\t\t</triangles>\n\t\t\t</mesh>\n\t\t</object>\n\t</resources>\n\t<build p:UUID=\"";
    xml += content_uuid(mesh, 3);
    xml += "\">\n\t\t<item objectid=\"1\" p:UUID=\"";
    xml += content_uuid(mesh, 2);
    xml += "\" />\n\t</build>\n</model>\n";
    xml.flush();
  }
  zip.end_entry();
  part(
      "[Content_Types].xml",
      R"(<?xml version="1.0" encoding="utf-8"?>)"
      "\n"
      R"(<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">)"
      "\n"
      "\t"
      R"(<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml" />)"
      "\n"
      "\t"
      R"(<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml" />)"
      "\n"
      "</Types>\n");
  part("_rels/.rels",
       R"(<?xml version="1.0" encoding="utf-8"?>)"
       "\n"
       R"(<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)"
       "\n"
       "\t"
       R"(<Relationship Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel" )"
       R"(Target="/3D/3dmodel.model" Id="rel0" />)"
       "\n"
       "</Relationships>\n");
  zip.finish();
}

}  // namespace isopatch::io
