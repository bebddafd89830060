// PLY header parsing. The header is plain text up to the line `end_header`; it is read with the
// same tokenizer as the ASCII bodies and never looked at past that line, so a binary body cannot
// confuse it.
#include "mesh/ply_header.hpp"

#include "mesh/io_util.hpp"

#include <limits>

namespace isopatch::io {
namespace {

struct TypeName {
  std::string_view name;
  PlyType type;
};

// Both spellings of the PLY scalar types.
constexpr TypeName kTypeNames[] = {
    {"char", PlyType::Int8},       {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},     {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},   {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},     {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},   {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
};

bool type_from_name(std::string_view word, PlyType& type) {
  for (const TypeName& t : kTypeNames)
    if (t.name == word) {
      type = t.type;
      return true;
    }
  return false;
}

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& name) : tokens_(bytes), name_(name) {}

  PlyHeader parse() {
    if (tokens_.next_on_line() != "ply" || !tokens_.next_on_line().empty())
      fail(name_, "not a PLY file (no 'ply' magic line)");
    bool has_format = false;
    for (;;) {
      if (!tokens_.next_line()) fail(name_, "header has no end_header line");
      const std::string_view keyword = tokens_.next_on_line();
      if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header") {
        end_of_line();
        break;
      }
      if (keyword == "format") {
        if (has_format) error("a second format line");
        read_format();
        has_format = true;
      } else if (keyword == "element") {
        read_element();
      } else if (keyword == "property") {
        read_property();
      } else {
        error("unknown header keyword " + io::quoted(keyword));
      }
    }
    if (!has_format) fail(name_, "header has no format line");
    tokens_.next_line();
    header_.body_offset = tokens_.position();
    header_.body_line = tokens_.line();
    return std::move(header_);
  }

 private:
  [[noreturn]] void error(const std::string& problem) { fail_at(name_, tokens_.line(), problem); }

  void end_of_line() {
    if (const std::string_view extra = tokens_.next_on_line(); !extra.empty())
      error("unexpected " + io::quoted(extra) + " at the end of a header line");
  }

  std::string_view word(const char* what) {
    const std::string_view token = tokens_.next_on_line();
    if (token.empty()) error(std::string("missing ") + what);
    return token;
  }

  PlyType type(const char* what) {
    const std::string_view token = word(what);
    PlyType t{};
    if (!type_from_name(token, t)) error("unknown PLY type " + io::quoted(token));
    return t;
  }

  void read_format() {
    const std::string_view encoding = word("encoding");
    if (encoding == "ascii") {
      header_.encoding = PlyEncoding::Ascii;
    } else if (encoding == "binary_little_endian") {
      header_.encoding = PlyEncoding::BinaryLittleEndian;
    } else if (encoding == "binary_big_endian") {
      header_.encoding = PlyEncoding::BinaryBigEndian;
    } else {
      error("unknown PLY encoding " + io::quoted(encoding));
    }
    if (const std::string_view version = word("version"); version != "1.0")
      error("unsupported PLY version " + io::quoted(version));
    end_of_line();
  }

  void read_element() {
    PlyElement element;
    element.name = std::string(word("element name"));
    const std::string_view count = word("element count");
    if (!parse_uint(count, element.count)) error("bad element count " + io::quoted(count));
    end_of_line();
    for (const PlyElement& e : header_.elements)
      if (e.name == element.name) error("element '" + e.name + "' is declared twice");
    header_.elements.push_back(std::move(element));
  }

  void read_property() {
    if (header_.elements.empty()) error("property before any element");
    PlyProperty property;
    const std::string_view first = word("property type");
    if (first == "list") {
      property.is_list = true;
      property.count_type = type("list count type");
      if (!ply_type_is_integer(property.count_type)) error("list count type must be an integer type");
      property.type = type("list item type");
    } else if (!type_from_name(first, property.type)) {
      error("unknown PLY type " + io::quoted(first));
    }
    property.name = std::string(word("property name"));
    end_of_line();
    PlyElement& element = header_.elements.back();
    if (element.find(property.name) >= 0)
      error("property '" + property.name + "' of element '" + element.name + "' is declared twice");
    element.properties.push_back(std::move(property));
  }

  Tokens tokens_;
  const std::string& name_;
  PlyHeader header_;
};

}  // namespace

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::Float32 && type != PlyType::Float64;
}

double ply_type_min(PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return std::numeric_limits<std::int8_t>::min();
    case PlyType::Int16:
      return std::numeric_limits<std::int16_t>::min();
    case PlyType::Int32:
      return std::numeric_limits<std::int32_t>::min();
    case PlyType::UInt8:
    case PlyType::UInt16:
    case PlyType::UInt32:
      return 0.0;
    case PlyType::Float32:
    case PlyType::Float64:
      break;
  }
  return -std::numeric_limits<double>::infinity();
}

double ply_type_max(PlyType type) {
  switch (type) {
    case PlyType::Int8:
      return std::numeric_limits<std::int8_t>::max();
    case PlyType::UInt8:
      return std::numeric_limits<std::uint8_t>::max();
    case PlyType::Int16:
      return std::numeric_limits<std::int16_t>::max();
    case PlyType::UInt16:
      return std::numeric_limits<std::uint16_t>::max();
    case PlyType::Int32:
      return std::numeric_limits<std::int32_t>::max();
    case PlyType::UInt32:
      return std::numeric_limits<std::uint32_t>::max();
    case PlyType::Float32:
    case PlyType::Float64:
      break;
  }
  return std::numeric_limits<double>::infinity();
}

int PlyElement::find(std::string_view property) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return static_cast<int>(i);
  return -1;
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name) {
  return HeaderParser(bytes, name).parse();
}

}  // namespace isopatch::io
