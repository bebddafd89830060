// The .npy and NRRD readers: round trips of hand-built files, and every kind of bad file.
#include <gtest/gtest.h>
#include <zlib.h>
#include <isopatch/error.hpp>
#include <isopatch/volume_io.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace isopatch {
namespace {

/// A .npy file (version 1) with `header` as the dict and `data` after it.
std::string npy(const std::string& dict, const std::string& data) {
  std::string header = dict;
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(header.size() & 0xff);
  out += static_cast<char>(header.size() >> 8);
  return out + header + data;
}

template <class T>
std::string bytes_of(const std::vector<T>& values, bool big_endian = false) {
  std::string out;
  for (const T v : values) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big_endian)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out.append(b, sizeof(T));
  }
  return out;
}

std::vector<float> ramp(std::size_t n) {
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<float>(i) * 0.5f - 3.0f;
  return v;
}

std::string error_of(std::string_view bytes, VolumeFormat format) {
  try {
    decode_volume(bytes, format, "f");
  } catch (const IoError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Npy, COrderFloat32) {
  const auto values = ramp(2 * 3 * 4);
  const Volume v =
      decode_volume(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3, 4), }", bytes_of(values)),
                    VolumeFormat::Npy);
  ASSERT_EQ(v.shape, (std::array<std::size_t, 3>{2, 3, 4}));
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(v.at(i, j, k), values[(i * 3 + j) * 4 + k]);
  EXPECT_EQ(v.spacing, Vec3::Ones());
  EXPECT_EQ(v.origin, Vec3::Zero());
}

TEST(Npy, FortranOrderBigEndianInt16) {
  std::vector<std::int16_t> values(2 * 3 * 4);
  for (std::size_t n = 0; n < values.size(); ++n) values[n] = static_cast<std::int16_t>(100 * n - 900);
  const Volume v = decode_volume(
      npy("{'descr': '>i2', 'fortran_order': True, 'shape': (2, 3, 4), }", bytes_of(values, true)),
      VolumeFormat::Npy);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(v.at(i, j, k), values[i + 2 * (j + 3 * k)]);
}

TEST(Npy, BadFilesNameTheProblem) {
  const std::string data = bytes_of(ramp(24));
  const auto head = [](const std::string& descr, const std::string& shape) {
    return "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  };
  EXPECT_NE(error_of("not numpy at all", VolumeFormat::Npy).find("not a .npy file"), std::string::npos);
  EXPECT_NE(error_of(npy(head("<c8", "(2, 3, 4)"), data), VolumeFormat::Npy).find("unsupported dtype '<c8'"),
            std::string::npos);
  EXPECT_NE(error_of(npy(head("<f4", "(6, 4)"), data), VolumeFormat::Npy).find("2 dimensions"),
            std::string::npos);
  EXPECT_NE(
      error_of(npy(head("<f4", "(2, 3, 4)"), data.substr(0, 50)), VolumeFormat::Npy).find("holds 50 bytes"),
      std::string::npos);
  EXPECT_NE(error_of(npy(head("<f4", "(2, 3, 4)"), data + "x"), VolumeFormat::Npy).find("holds 97 bytes"),
            std::string::npos);
  EXPECT_NE(error_of(npy(head("<f4", "(4000000000, 4000000000, 4000000000)"), data), VolumeFormat::Npy)
                .find("more than"),
            std::string::npos);
  EXPECT_NE(error_of(npy(head("<f4", "(1, 3, 8)"), data), VolumeFormat::Npy).find("at least 2 samples"),
            std::string::npos);
  EXPECT_NE(error_of(npy("{'descr': [('a', '<f4')], 'fortran_order': False, 'shape': (2, 3, 4), }", data),
                     VolumeFormat::Npy)
                .find("not a plain scalar type"),
            std::string::npos);
  EXPECT_NE(error_of(npy("{'descr': '<f4', 'shape': (2, 3, 4), }", data), VolumeFormat::Npy).find("lacks"),
            std::string::npos);
  std::vector<float> with_nan = ramp(24);
  with_nan[(1 * 3 + 2) * 4 + 3] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(error_of(npy(head("<f4", "(2, 3, 4)"), bytes_of(with_nan)), VolumeFormat::Npy)
                .find("NaN at index (1, 2, 3)"),
            std::string::npos);
  // A header length running past the end of the file.
  std::string cut = npy(head("<f4", "(2, 3, 4)"), data).substr(0, 40);
  EXPECT_NE(error_of(cut, VolumeFormat::Npy).find("truncated"), std::string::npos);
}

std::string gzip(const std::string& data) {
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&z, data.size()) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

std::string nrrd_header(const std::string& encoding, const std::string& extra = "",
                        const std::string& sizes = "4 3 2") {
  return "NRRD0004\n# a comment\ntype: float\ndimension: 3\nsizes: " + sizes + "\nencoding: " + encoding +
         "\nendian: little\n" + extra + "\n";
}

TEST(Nrrd, RawAndGzipFastestAxisIsX) {
  const auto values = ramp(24);
  const std::string extra =
      "space directions: (0.5,0,0) (0,2,0) (0,0,1.5)\nspace origin: (1,-2,3)\nkey:=value\n";
  for (const std::string encoding : {"raw", "gzip"}) {
    const std::string data = encoding == "raw" ? bytes_of(values) : gzip(bytes_of(values));
    const Volume v = decode_volume(nrrd_header(encoding, extra) + data, VolumeFormat::Nrrd);
    ASSERT_EQ(v.shape, (std::array<std::size_t, 3>{4, 3, 2})) << encoding;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(v.at(i, j, k), values[i + 4 * (j + 3 * k)]);
    EXPECT_EQ(v.spacing, Vec3(0.5, 2, 1.5));
    EXPECT_EQ(v.origin, Vec3(1, -2, 3));
  }
  const Volume s =
      decode_volume(nrrd_header("raw", "spacings: 2 3 4\n") + bytes_of(values), VolumeFormat::Nrrd);
  EXPECT_EQ(s.spacing, Vec3(2, 3, 4));
}

TEST(Nrrd, BadFilesNameTheProblem) {
  const std::string data = bytes_of(ramp(24));
  const auto err = [](const std::string& bytes) { return error_of(bytes, VolumeFormat::Nrrd); };
  EXPECT_NE(err("P6 not nrrd").find("not a NRRD file"), std::string::npos);
  EXPECT_NE(err(nrrd_header("raw") + data.substr(0, 90)).find("holds 90 bytes"), std::string::npos);
  EXPECT_NE(err(nrrd_header("raw", "", "4 3 3") + data).find("(144 bytes)"), std::string::npos);
  EXPECT_NE(err(nrrd_header("gzip") + gzip(data.substr(0, 60))).find("60 bytes"), std::string::npos);
  EXPECT_NE(err(nrrd_header("gzip") + gzip(data + "more")).find("more than"), std::string::npos);
  EXPECT_NE(err(nrrd_header("gzip") + "garbage that is not gzip").find("corrupt"), std::string::npos);
  // 4 GB declared, 30 bytes given: refused before anything is allocated or inflated.
  EXPECT_NE(err(nrrd_header("gzip", "", "1000 1000 1000") + gzip(data.substr(0, 8))).find("cannot hold"),
            std::string::npos);
  EXPECT_NE(err(nrrd_header("ascii") + "1 2 3").find("encoding 'ascii' is not supported"), std::string::npos);
  EXPECT_NE(
      err(nrrd_header("raw", "space directions: (1,1,0) (0,1,0) (0,0,1)\n") + data).find("axis-aligned"),
      std::string::npos);
  EXPECT_NE(err(nrrd_header("raw", "data file: other.raw\n")).find("detached"), std::string::npos);
  EXPECT_NE(err(nrrd_header("raw", "", "4 3 2 1") + data).find("3 numbers"), std::string::npos);
  EXPECT_NE(err("NRRD0004\ntype: float\ndimension: 3\nsizes: 4 3 2\n").find("no end"), std::string::npos);
  EXPECT_NE(err("NRRD0004\ntype: complex\n\n").find("unsupported NRRD type 'complex'"), std::string::npos);
  EXPECT_NE(err(nrrd_header("raw", "spacings: 1 0 1\n") + data).find("spacing"), std::string::npos);
  EXPECT_NE(err(nrrd_header("raw", "", "99999999999 99999999999 2") + data).find("too large"),
            std::string::npos);
}

TEST(VolumeFiles, FormatFromExtension) {
  EXPECT_TRUE(is_volume_path("a/b.NPY"));
  EXPECT_TRUE(is_volume_path("scan.nrrd"));
  EXPECT_FALSE(is_volume_path("mesh.ply"));
  EXPECT_THROW(volume_format_from_path("x.vtk"), IoError);
  EXPECT_THROW(read_volume("/nonexistent/volume.npy"), IoError);
}

}  // namespace
}  // namespace isopatch
