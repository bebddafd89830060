// NRRD: a magic line "NRRD000N", header lines "field: value" (and "key:=value" pairs, ignored) up to
// an empty line, then the data. Fields read: type, dimension, sizes, encoding, endian, spacings,
// space directions, space origin; "data file" (detached data) and skips are refused.
#include "volume/nrrd_reader.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "mesh/io_util.hpp"
#include "volume/gunzip.hpp"
#include "volume/scalar_decode.hpp"

namespace isopatch::volume_io {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

/// Three numbers separated by spaces ("1 1 1").
std::optional<Vec3> three_numbers(std::string_view text) {
  io::Tokens tokens(text);
  Vec3 v;
  for (int a = 0; a < 3; ++a)
    if (!io::parse_double(tokens.next(), v[a]) || !std::isfinite(v[a])) return std::nullopt;
  if (!tokens.at_end()) return std::nullopt;
  return v;
}

/// A vector "(a,b,c)" starting at `pos` of `text`; advances pos past it.
std::optional<Vec3> parenthesized(std::string_view text, std::size_t& pos) {
  while (pos < text.size() && text[pos] == ' ') ++pos;
  if (pos >= text.size() || text[pos] != '(') return std::nullopt;
  const std::size_t end = text.find(')', pos);
  if (end == std::string_view::npos) return std::nullopt;
  std::string inner(text.substr(pos + 1, end - pos - 1));
  for (char& c : inner)
    if (c == ',') c = ' ';
  pos = end + 1;
  return three_numbers(inner);
}

struct Header {
  std::optional<ScalarType> type;
  std::string type_name;
  int dimension = 0;
  std::vector<std::uint64_t> sizes;
  std::string encoding;
  bool big_endian = false;
  std::optional<Vec3> spacings;
  std::optional<Vec3> directions;  ///< the diagonal of axis-aligned space directions
  std::optional<Vec3> origin;
};

void read_field(Header& h, std::string_view field, std::string_view value, const std::string& name) {
  if (field == "type") {
    h.type_name = std::string(value);
    h.type = nrrd_scalar_type(value);
    if (!h.type)
      io::fail(name, "unsupported NRRD type " + io::quoted(h.type_name) +
                         " (want a signed or unsigned integer of 1 to 8 bytes, float or double)");
  } else if (field == "dimension") {
    std::int64_t d = 0;
    if (!io::parse_int(value, d)) io::fail(name, "bad NRRD dimension " + io::quoted(value));
    h.dimension = static_cast<int>(std::min<std::int64_t>(d, 1000));
  } else if (field == "sizes") {
    io::Tokens tokens(value);
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
      std::uint64_t n = 0;
      if (!io::parse_uint(t, n) || h.sizes.size() == 16)
        io::fail(name, "bad NRRD sizes " + io::quoted(value));
      h.sizes.push_back(n);
    }
  } else if (field == "encoding") {
    h.encoding = std::string(value);
  } else if (field == "endian") {
    if (value != "little" && value != "big") io::fail(name, "bad NRRD endian " + io::quoted(value));
    h.big_endian = value == "big";
  } else if (field == "spacings") {
    h.spacings = three_numbers(value);
    if (!h.spacings) io::fail(name, "NRRD spacings must be three finite numbers, not " + io::quoted(value));
  } else if (field == "space directions") {
    std::size_t pos = 0;
    Vec3 diagonal;
    for (int a = 0; a < 3; ++a) {
      const std::optional<Vec3> d = parenthesized(value, pos);
      if (!d) io::fail(name, "NRRD space directions must be three vectors (a,b,c), not " + io::quoted(value));
      for (int b = 0; b < 3; ++b)
        if (b != a && (*d)[b] != 0.0)
          io::fail(name, "NRRD space directions must be axis-aligned (a diagonal matrix), not " +
                             io::quoted(value));
      diagonal[a] = (*d)[a];
    }
    if (!trim(value.substr(pos)).empty())
      io::fail(name, "NRRD space directions: extra text in " + io::quoted(value));
    h.directions = diagonal;
  } else if (field == "space origin") {
    std::size_t pos = 0;
    h.origin = parenthesized(value, pos);
    if (!h.origin || !trim(value.substr(pos)).empty())
      io::fail(name, "NRRD space origin must be a vector (a,b,c), not " + io::quoted(value));
  } else if (field == "data file" || field == "datafile") {
    io::fail(name, "detached NRRD data (\"data file\") is not supported: attach the data to the header");
  } else if (field == "line skip" || field == "lineskip" || field == "byte skip" || field == "byteskip") {
    if (value != "0") io::fail(name, "NRRD " + io::quoted(field) + " is not supported");
  }
  // Every other field (space, kinds, units, centers, labels, content, ...) does not change the samples.
}

}  // namespace

Volume decode_nrrd(std::string_view bytes, const std::string& name) {
  if (bytes.substr(0, 7) != "NRRD000" || bytes.size() < 9 || bytes[7] < '1' || bytes[7] > '5')
    io::fail(name, "not a NRRD file (no NRRD0001..NRRD0005 magic)");
  std::size_t pos = bytes.find('\n');
  if (pos == std::string_view::npos) io::fail(name, "the NRRD header is truncated");
  ++pos;
  Header h;
  std::size_t line_number = 1;
  while (true) {
    const std::size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos)
      io::fail(name, "the NRRD header has no end (an empty line before the data)");
    ++line_number;
    const std::string_view line = trim(bytes.substr(pos, end - pos));
    pos = end + 1;
    if (line.empty()) break;
    if (line.front() == '#') continue;
    if (line.find(":=") != std::string_view::npos) continue;  // key/value pair
    const std::size_t colon = line.find(": ");
    if (colon == std::string_view::npos)
      io::fail_at(name, line_number, "not a NRRD field: " + io::quoted(line));
    read_field(h, line.substr(0, colon), trim(line.substr(colon + 2)), name);
  }
  if (!h.type) io::fail(name, "the NRRD header has no type");
  if (h.dimension != 3)
    io::fail(name, "the NRRD volume has dimension " + std::to_string(h.dimension) + "; a volume needs 3");
  if (h.sizes.size() != 3) io::fail(name, "the NRRD sizes must be 3 numbers");
  std::array<std::size_t, 3> shape{};
  for (int a = 0; a < 3; ++a) {
    const std::uint64_t n = h.sizes[static_cast<std::size_t>(a)];
    if (n > kMaxVolumeSamples) io::fail(name, "the NRRD volume is too large");
    shape[static_cast<std::size_t>(a)] = static_cast<std::size_t>(n);
  }
  const std::size_t count = checked_sample_count(shape);
  if (count == 0)
    io::fail(name,
             "the NRRD volume is empty or has more than " + std::to_string(kMaxVolumeSamples) + " samples");
  const std::size_t need = count * scalar_size(*h.type);
  const std::string_view data = bytes.substr(pos);
  std::string inflated;
  const char* raw = nullptr;
  if (h.encoding == "raw") {
    if (data.size() != need)
      io::fail(name, "the NRRD header declares " + std::to_string(shape[0]) + " x " +
                         std::to_string(shape[1]) + " x " + std::to_string(shape[2]) + " " + h.type_name +
                         " samples (" + std::to_string(need) + " bytes) but the file holds " +
                         std::to_string(data.size()) + " bytes of data");
    raw = data.data();
  } else if (h.encoding == "gzip" || h.encoding == "gz") {
    inflated = gunzip_exactly(data, need, name);
    raw = inflated.data();
  } else if (h.encoding.empty()) {
    io::fail(name, "the NRRD header has no encoding");
  } else {
    io::fail(name, "NRRD encoding " + io::quoted(h.encoding) + " is not supported (want raw or gzip)");
  }
  Volume v;
  v.shape = shape;
  const std::size_t dims[3] = {shape[0], shape[1], shape[2]};
  v.samples = fastest_first_to_c_order(decode_scalars(raw, count, *h.type, h.big_endian), dims);
  if (h.spacings && h.directions) io::fail(name, "the NRRD header gives both spacings and space directions");
  if (h.spacings) v.spacing = *h.spacings;
  if (h.directions) v.spacing = *h.directions;
  if (h.origin) v.origin = *h.origin;
  for (int a = 0; a < 3; ++a)
    if (!(v.spacing[a] > 0.0))
      io::fail(name, "NRRD spacings must be > 0 on every axis (flipped axes are not supported)");
  return v;
}

}  // namespace isopatch::volume_io
