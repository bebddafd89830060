// numpy's .npy format: a magic string, a version, a header that is a Python dict literal
// {'descr': '<f8', 'fortran_order': False, 'shape': (n0, n1, n2), }, then the packed data.
#include "volume/npy_reader.hpp"

#include <cctype>
#include <cstdint>
#include <vector>

#include "mesh/io_util.hpp"
#include "volume/scalar_decode.hpp"

namespace isopatch::volume_io {

namespace {

/// A strict reader of the header's dict literal: string keys, values a string, True/False, or a
/// tuple of non-negative integers.
class HeaderParser {
 public:
  HeaderParser(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  struct Fields {
    std::string descr;
    bool fortran_order = false;
    std::vector<std::uint64_t> shape;
    bool has_descr = false, has_order = false, has_shape = false;
  };

  Fields parse() {
    Fields f;
    expect('{');
    while (true) {
      skip_space();
      if (peek() == '}') break;
      const std::string key = string_literal();
      expect(':');
      skip_space();
      if (key == "descr") {
        if (peek() != '\'' && peek() != '"')
          fail("dtype " + rest() + " is not a plain scalar type (want e.g. '<f8')");
        f.descr = string_literal();
        f.has_descr = true;
      } else if (key == "fortran_order") {
        f.fortran_order = boolean();
        f.has_order = true;
      } else if (key == "shape") {
        f.shape = tuple();
        f.has_shape = true;
      } else {
        fail("unknown header key " + io::quoted(key));
      }
      skip_space();
      if (peek() == ',') ++pos_;
    }
    if (!f.has_descr || !f.has_order || !f.has_shape)
      fail("the header lacks one of 'descr', 'fortran_order' and 'shape'");
    return f;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { io::fail(name_, "npy header: " + problem); }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  std::string rest() const { return io::quoted(text_.substr(pos_, 20)); }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  void expect(char c) {
    skip_space();
    if (peek() != c) fail(std::string("expected '") + c + "' at " + rest());
    ++pos_;
  }
  std::string string_literal() {
    skip_space();
    const char quote = peek();
    if (quote != '\'' && quote != '"') fail("expected a quoted key at " + rest());
    const std::size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string_view::npos) fail("unterminated string");
    std::string s(text_.substr(pos_ + 1, end - pos_ - 1));
    pos_ = end + 1;
    return s;
  }
  bool boolean() {
    if (text_.substr(pos_, 4) == "True") {
      pos_ += 4;
      return true;
    }
    if (text_.substr(pos_, 5) == "False") {
      pos_ += 5;
      return false;
    }
    fail("expected True or False at " + rest());
  }
  std::vector<std::uint64_t> tuple() {
    expect('(');
    std::vector<std::uint64_t> values;
    while (true) {
      skip_space();
      if (peek() == ')') break;
      const std::size_t start = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      std::uint64_t v = 0;
      if (start == pos_ || !io::parse_uint(text_.substr(start, pos_ - start), v))
        fail("expected a dimension at " + io::quoted(text_.substr(start, 20)));
      if (values.size() == 8) fail("more than 8 dimensions");
      values.push_back(v);
      skip_space();
      if (peek() == ',')
        ++pos_;
      else if (peek() != ')')
        fail("expected ',' or ')' at " + rest());
    }
    ++pos_;
    return values;
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
};

}  // namespace

NpyLayout read_npy_layout(std::string_view bytes, const std::string& name, std::size_t max_samples) {
  static constexpr std::string_view kMagic = "\x93NUMPY";
  if (bytes.size() < 10 || bytes.substr(0, 6) != kMagic)
    io::fail(name, "not a .npy file (no \\x93NUMPY magic)");
  const int major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_len = 0, offset = 0;
  if (major == 1) {
    header_len = io::load_scalar<std::uint16_t>(bytes.data() + 8, false);
    offset = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) io::fail(name, "the .npy header is truncated");
    header_len = io::load_scalar<std::uint32_t>(bytes.data() + 8, false);
    offset = 12;
  } else {
    io::fail(name, "unsupported .npy format version " + std::to_string(major));
  }
  if (header_len > bytes.size() - offset) io::fail(name, "the .npy header is truncated");
  const HeaderParser::Fields f = HeaderParser(bytes.substr(offset, header_len), name).parse();
  NpyLayout layout;
  layout.data_offset = offset + header_len;
  layout.descr = f.descr;
  layout.fortran_order = f.fortran_order;

  const std::string& d = f.descr;
  if (d.size() < 3 || (d[0] != '<' && d[0] != '>' && d[0] != '|' && d[0] != '='))
    io::fail(name, "unsupported dtype " + io::quoted(d) + " (want a scalar type such as '<f8')");
  layout.big_endian = d[0] == '>';
  std::uint64_t size = 0;
  const auto type = io::parse_uint(std::string_view(d).substr(2), size) && size <= 16
                        ? numpy_scalar_type(d[1], static_cast<std::size_t>(size))
                        : std::nullopt;
  if (!type)
    io::fail(name, "unsupported dtype " + io::quoted(d) +
                       " (want bool, a signed or unsigned integer of 1 to 8 bytes, float32 or float64)");
  layout.type = *type;
  if (f.shape.size() != 3)
    io::fail(name, "the array has " + std::to_string(f.shape.size()) + " dimensions; a volume needs 3");
  std::size_t count = 1;
  for (int a = 0; a < 3; ++a) {
    const std::uint64_t n = f.shape[static_cast<std::size_t>(a)];
    layout.shape[static_cast<std::size_t>(a)] = n > max_samples ? 0 : static_cast<std::size_t>(n);
    count = n == 0 || n > max_samples || count > max_samples / n ? 0 : count * static_cast<std::size_t>(n);
  }
  const std::string shape_text =
      std::to_string(f.shape[0]) + " x " + std::to_string(f.shape[1]) + " x " + std::to_string(f.shape[2]);
  if (count == 0)
    io::fail(name, "the array is " + shape_text + ": empty, or more than " + std::to_string(max_samples) +
                       " samples");
  layout.count = count;
  const std::size_t need = count * scalar_size(*type);
  if (bytes.size() - layout.data_offset != need)
    io::fail(name, "the array is " + shape_text + " of " + io::quoted(d) + " (" + std::to_string(need) +
                       " bytes) but the file holds " + std::to_string(bytes.size() - layout.data_offset) +
                       " bytes of data");
  return layout;
}

Volume decode_npy(std::string_view bytes, const std::string& name) {
  const NpyLayout layout = read_npy_layout(bytes, name, kMaxVolumeSamples);
  Volume v;
  v.shape = layout.shape;
  v.samples = decode_scalars(bytes.data() + layout.data_offset, layout.count, layout.type, layout.big_endian);
  if (layout.fortran_order) {
    const std::size_t dims[3] = {layout.shape[0], layout.shape[1], layout.shape[2]};
    v.samples = fastest_first_to_c_order(v.samples, dims);
  }
  return v;
}

}  // namespace isopatch::volume_io
