// Mesh readers on malformed input: truncated files, random byte damage, lying headers, indices out of
// range, non-finite numbers, degenerate or oversized faces and plain garbage. Each must either be
// rejected with a one-line IoError naming the file, or (only when the damage leaves a valid file)
// parse into a mesh that passes Mesh::validate(). Nothing may crash, hang or allocate what the
// header claims without the bytes to back it.
#include <isopatch/error.hpp>
#include <isopatch/mesh_io.hpp>

#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

namespace isopatch {
namespace {

constexpr MeshFormat kFormats[] = {MeshFormat::Obj, MeshFormat::PlyAscii, MeshFormat::PlyBinary,
                                   MeshFormat::Off, MeshFormat::Stl};

const char* label(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj:
      return "obj";
    case MeshFormat::PlyAscii:
      return "ply-ascii";
    case MeshFormat::PlyBinary:
      return "ply-binary";
    case MeshFormat::Off:
      return "off";
    case MeshFormat::Stl:
      return "stl";
    case MeshFormat::Glb:
      return "glb";
    case MeshFormat::ThreeMf:
      return "3mf";
  }
  return "?";
}

// True when the bytes parse; false when they are rejected with a well-formed IoError. Any other
// exception escapes and fails the test.
bool parses(std::string_view bytes, MeshFormat format, std::size_t max_vertices = SIZE_MAX,
            std::size_t max_triangles = SIZE_MAX) {
  try {
    const Mesh m = decode_mesh(bytes, format, "damaged.file");
    EXPECT_NO_THROW(m.validate());
    EXPECT_LE(m.vertex_count(), max_vertices);
    EXPECT_LE(m.triangle_count(), max_triangles);
    return true;
  } catch (const IoError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("damaged.file", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return false;
  }
}

// Expects an IoError whose message contains `part`.
void expect_rejected(std::string_view bytes, MeshFormat format, const std::string& part = "") {
  try {
    decode_mesh(bytes, format, "bad.file");
    ADD_FAILURE() << label(format) << " accepted:\n" << bytes.substr(0, 200);
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

std::string ply_binary_header(const std::string& elements) {
  return "ply\nformat binary_little_endian 1.0\n" + elements + "end_header\n";
}

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);  // tests run on little-endian hosts
}

// Three float vertices of a binary PLY.
std::string three_float_vertices() {
  std::string out;
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(out, v);
  return out;
}

const std::string kPlyVertices = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

TEST(MeshIoMalformed, EveryTruncationIsRejectedOrValid) {
  const Mesh mesh = test::icosahedron();
  for (MeshFormat format : kFormats) {
    SCOPED_TRACE(label(format));
    const std::string bytes = encode_mesh(mesh, format);
    // Text formats with declared counts can only parse when the cut falls inside the last line.
    const std::size_t last_line = bytes.rfind('\n', bytes.size() - 2) + 1;
    std::size_t parsed = 0;
    for (std::size_t length = 0; length < bytes.size(); ++length) {
      const bool ok = parses(std::string_view(bytes).substr(0, length), format, mesh.vertex_count(),
                             mesh.triangle_count());
      parsed += ok;
      if (format == MeshFormat::PlyBinary || format == MeshFormat::Stl) {
        EXPECT_FALSE(ok) << "binary file cut at " << length << " of " << bytes.size();
      } else if (format != MeshFormat::Obj && length <= last_line) {
        EXPECT_FALSE(ok) << "text file cut at " << length << " of " << bytes.size();
      }
    }
    RecordProperty(std::string(label(format)) + "_truncations_parsed", static_cast<int>(parsed));
  }
}

TEST(MeshIoMalformed, TruncatedFilesOnDiskAreRejected) {
  const test::TempDir dir;
  for (const char* file : {"m.ply", "m.stl", "m.off"}) {
    const std::string full = encode_mesh(test::icosahedron(), format_from_path(file));
    for (std::size_t length :
         {std::size_t{0}, std::size_t{3}, full.size() / 3, full.size() / 2, full.size() - 40}) {
      {
        std::ofstream out(dir.file(file), std::ios::binary | std::ios::trunc);
        out.write(full.data(), static_cast<std::streamsize>(length));
      }
      try {
        read_mesh(dir.file(file));
        ADD_FAILURE() << file << " cut at " << length << " was accepted";
      } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(dir.file(file)), std::string::npos) << e.what();
      }
    }
  }
}

TEST(MeshIoMalformed, RandomByteDamageNeverCrashes) {
  std::mt19937 random(12345);
  const Mesh mesh = test::icosahedron();
  for (MeshFormat format : kFormats) {
    SCOPED_TRACE(label(format));
    const std::string bytes = encode_mesh(mesh, format);
    std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255), edits(1, 4);
    const std::string alphabet = "0123456789-+.eE \n/#nainf";
    std::uniform_int_distribution<std::size_t> letter(0, alphabet.size() - 1);
    int rejected = 0;
    for (int trial = 0; trial < 3000; ++trial) {
      std::string damaged = bytes;
      for (int e = edits(random); e > 0; --e) {
        const std::size_t at = position(random) % damaged.size();
        switch (trial % 3) {
          case 0:
            damaged[at] = static_cast<char>(byte(random));
            break;
          case 1:
            damaged[at] = alphabet[letter(random)];
            break;
          default:
            damaged.erase(at, 1 + at % 7);
            break;
        }
        if (damaged.empty()) break;
      }
      rejected += !parses(damaged, format);
    }
    EXPECT_GT(rejected, 0);
    RecordProperty(std::string(label(format)) + "_damaged_rejected", rejected);
  }
}

TEST(MeshIoMalformed, LyingCountsAreRejectedBeforeAllocating) {
  const std::string vertices = three_float_vertices();
  expect_rejected(
      ply_binary_header("element vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n") +
          vertices,
      MeshFormat::PlyBinary, "vertex");
  expect_rejected(
      ply_binary_header(kPlyVertices + "element face 1000000000\nproperty list uchar int vertex_indices\n") +
          vertices,
      MeshFormat::PlyBinary, "face");
  expect_rejected(
      ply_binary_header(kPlyVertices + "element junk 18446744073709551615\nproperty list uchar int a\n") +
          vertices,
      MeshFormat::PlyBinary, "junk");
  expect_rejected(
      ply_binary_header(kPlyVertices + "element junk 18446744073709551616\nproperty uchar a\n") + vertices,
      MeshFormat::PlyBinary, "count");
  expect_rejected(ply_binary_header(kPlyVertices + "element junk -1\nproperty uchar a\n") + vertices,
                  MeshFormat::PlyBinary, "count");
  // A list claiming 255 indices with only three behind it.
  std::string face = vertices;
  put(face, std::uint8_t{255});
  for (std::int32_t i : {0, 1, 2}) put(face, i);
  expect_rejected(
      ply_binary_header(kPlyVertices + "element face 1\nproperty list uchar int vertex_indices\n") + face,
      MeshFormat::PlyBinary, "face 0 is cut short");
  expect_rejected(
      "ply\nformat ascii 1.0\nelement vertex 900000000\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n",
      MeshFormat::PlyAscii, "vertex");
  expect_rejected("OFF\n1000000000 1 0\n0 0 0\n", MeshFormat::Off, "1000000000 vertices");
  expect_rejected("OFF\n3 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Off, "faces");
  expect_rejected("OFF\n-3 1 0\n", MeshFormat::Off, "count");
  expect_rejected("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", MeshFormat::Off,
                  "after the last face");

  std::string stl(80, ' ');
  put(stl, std::uint32_t{0xFFFFFFFF});
  stl += std::string(50, '\0');
  expect_rejected(stl, MeshFormat::Stl, "4294967295 triangles");
  stl.replace(80, 4, "\2\0\0\0", 4);
  expect_rejected(stl, MeshFormat::Stl, "2 triangles");
}

TEST(MeshIoMalformed, ElementsWithoutPropertiesCostNothing) {
  // No bytes per item: a huge count is harmless and is skipped at once.
  const Mesh m = decode_mesh(
      ply_binary_header(kPlyVertices + "element nothing 18446744073709551615\n") + three_float_vertices(),
      MeshFormat::PlyBinary);
  EXPECT_EQ(m.vertex_count(), 3u);
}

TEST(MeshIoMalformed, VertexElementWithoutPropertiesIsRejectedBeforeAllocating) {
  // Found by fuzz_mesh_reader: a property-less vertex element has no size per item, so its count was
  // not bounded by the file size and 300 million positions were allocated.
  expect_rejected("ply\nformat ascii 1.0\nelement vertex 321000000\nend_header\n", MeshFormat::PlyAscii,
                  "no properties");
  expect_rejected("ply\nformat binary_little_endian 1.0\nelement vertex 321000000\nend_header\n",
                  MeshFormat::PlyBinary, "no properties");
}

TEST(MeshIoMalformed, IndicesOutOfRangeAreRejected) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_rejected(obj + "f 1 2 4\n", MeshFormat::Obj, "vertex 4 but 3 vertices");
  expect_rejected(obj + "f 0 1 2\n", MeshFormat::Obj, "vertex 0");
  expect_rejected(obj + "f -4 -2 -1\n", MeshFormat::Obj, "vertex -4");
  expect_rejected("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n", MeshFormat::Obj, "vertex 3");
  expect_rejected(obj + "f 1 2 99999999999999999999\n", MeshFormat::Obj, "corner");

  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  expect_rejected(off + "3 0 1 3\n", MeshFormat::Off, "refers to vertex 3 but there are 3 vertices");
  expect_rejected(off + "3 0 1 -1\n", MeshFormat::Off, "vertex -1");

  const std::string ply =
      "ply\nformat ascii 1.0\n" + kPlyVertices +
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  expect_rejected(ply + "3 0 1 3\n", MeshFormat::PlyAscii,
                  "face 0 refers to vertex 3 but there are 3 vertices");
  expect_rejected(ply + "3 0 -1 2\n", MeshFormat::PlyAscii, "vertex -1");

  std::string binary = three_float_vertices();
  put(binary, std::uint8_t{3});
  for (std::int32_t i : {0, 99, 2}) put(binary, i);
  expect_rejected(
      ply_binary_header(kPlyVertices + "element face 1\nproperty list uchar int vertex_indices\n") + binary,
      MeshFormat::PlyBinary, "bad.file: face 0 refers to vertex 99 but there are 3 vertices");
}

TEST(MeshIoMalformed, NonFiniteOrBadNumbersAreRejected) {
  for (const char* x : {"nan", "inf", "-inf", "1e999", "0x10", "1..2", "1e", "--1", "++1", "1,5"}) {
    SCOPED_TRACE(x);
    expect_rejected(std::string("v ") + x + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::Obj);
    expect_rejected(std::string("OFF\n3 1 0\n") + x + " 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", MeshFormat::Off);
    expect_rejected(
        std::string("ply\nformat ascii 1.0\n") + kPlyVertices + "end_header\n" + x + " 0 0\n1 0 0\n0 1 0\n",
        MeshFormat::PlyAscii);
  }
  std::string binary = three_float_vertices();
  binary.replace(4, 4, "\0\0\xc0\x7f", 4);  // a float NaN
  expect_rejected(ply_binary_header(kPlyVertices) + binary, MeshFormat::PlyBinary, "not finite");

  std::string stl = encode_mesh(test::octahedron(), MeshFormat::Stl);
  stl.replace(84 + 12, 4, "\0\0\x80\x7f", 4);  // +inf in the first corner
  expect_rejected(stl, MeshFormat::Stl, "non-finite");
  // Out of range for the declared type.
  expect_rejected("ply\nformat ascii 1.0\n" + kPlyVertices +
                      "property uchar red\nend_header\n0 0 0 300\n1 0 0 0\n0 1 0 0\n",
                  MeshFormat::PlyAscii, "out of range");
}

TEST(MeshIoMalformed, DegenerateOrOversizedFacesAreRejected) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_rejected(obj + "f 1 2\n", MeshFormat::Obj, "2 vertices");
  expect_rejected(obj + "f 1 1 2\n", MeshFormat::Obj, "repeats");
  std::string big_face = obj + "f";
  for (int i = 0; i < 1001; ++i) big_face.append(i % 3 == 0 ? " 1" : i % 3 == 1 ? " 2" : " 3");
  expect_rejected(big_face + "\n", MeshFormat::Obj, "1001 vertices");

  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  expect_rejected(off + "2 0 1 # a face needs 3 vertices\n", MeshFormat::Off, "2 vertices");
  expect_rejected(off + "1001 0 1 2\n", MeshFormat::Off, "1001 vertices");
  expect_rejected(off + "4 0 1 2\n", MeshFormat::Off, "fewer than 4");

  std::string binary = three_float_vertices();
  put(binary, std::uint16_t{1001});
  for (int i = 0; i < 1001; ++i) put(binary, std::int32_t{i % 3});
  expect_rejected(
      ply_binary_header(kPlyVertices + "element face 1\nproperty list ushort int vertex_indices\n") + binary,
      MeshFormat::PlyBinary, "1001 vertices");
  std::string two = three_float_vertices();
  put(two, std::uint8_t{2});
  for (std::int32_t i : {0, 1}) put(two, i);
  expect_rejected(
      ply_binary_header(kPlyVertices + "element face 1\nproperty list uchar int vertex_indices\n") + two,
      MeshFormat::PlyBinary, "2 vertices");
}

TEST(MeshIoMalformed, BadPlyHeadersAreRejected) {
  const std::string body = "end_header\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string good = "ply\nformat ascii 1.0\n" + kPlyVertices;
  ASSERT_EQ(decode_mesh(good + body, MeshFormat::PlyAscii).vertex_count(), 3u);
  expect_rejected("plx\nformat ascii 1.0\n" + kPlyVertices + body, MeshFormat::PlyAscii, "magic");
  expect_rejected("ply\n" + kPlyVertices + body, MeshFormat::PlyAscii, "format");
  expect_rejected("ply\nformat ascii 2.0\n" + kPlyVertices + body, MeshFormat::PlyAscii, "version");
  expect_rejected("ply\nformat utf8 1.0\n" + kPlyVertices + body, MeshFormat::PlyAscii, "encoding");
  expect_rejected(good + "comment no end\n", MeshFormat::PlyAscii, "end_header");
  expect_rejected(good + "property float32x w\n" + body, MeshFormat::PlyAscii, "type");
  expect_rejected(good + "property list float int w\n" + body, MeshFormat::PlyAscii, "count type");
  expect_rejected(good + "property float x\n" + body, MeshFormat::PlyAscii, "twice");
  expect_rejected(good + "element vertex 0\n" + body, MeshFormat::PlyAscii, "twice");
  expect_rejected(good + "property float a-b\n" + "end_header\n0 0 0 1\n1 0 0 1\n0 1 0 1\n",
                  MeshFormat::PlyAscii, "attribute name");
  expect_rejected(good + "frobnicate 3\n" + body, MeshFormat::PlyAscii, "keyword");
  expect_rejected("ply\nformat ascii 1.0\nproperty float x\n" + body, MeshFormat::PlyAscii,
                  "before any element");
  expect_rejected(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nend_header\n0 0\n1 0\n0 "
      "1\n",
      MeshFormat::PlyAscii, "'z'");
  expect_rejected(
      "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n",
      MeshFormat::PlyAscii, "no 'vertex' element");
  expect_rejected(good + "element face 0\nproperty int vertex_indices\n" + body, MeshFormat::PlyAscii,
                  "not a list");
  expect_rejected(good + body + "7\n", MeshFormat::PlyAscii, "after the last element");
}

TEST(MeshIoMalformed, GarbageIsRejectedByEveryReader) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> byte(0, 255);
  std::string noise;
  for (int i = 0; i < 1000; ++i) noise += static_cast<char>(byte(random));
  for (MeshFormat format : kFormats) {
    SCOPED_TRACE(label(format));
    expect_rejected("hello world\nthis is not a mesh\n", format);
    expect_rejected(noise, format);
    expect_rejected(std::string(2000, '\0'), format);
  }
  expect_rejected("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n", MeshFormat::Stl, "ends");
  expect_rejected(
      "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 0 1 0\n endloop\n"
      " endfacet\n",
      MeshFormat::Stl, "endsolid");
  expect_rejected("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 zero\n",
                  MeshFormat::Stl, "bad number");
}

}  // namespace
}  // namespace isopatch
