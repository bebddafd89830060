// The layout checks of a .vdb file made before OpenVDB reads it (vdb_prescan.hpp).
#include "vdb/vdb_prescan.hpp"

#include <isopatch/error.hpp>

#include <cstdint>
#include <cstring>

namespace isopatch::vdb {

namespace {

/// Reads little-endian integers and length-prefixed strings from a byte range, refusing any read past
/// its end.
class Cursor {
 public:
  Cursor(std::string_view bytes, std::size_t at, std::size_t end, const std::string& name)
      : bytes_(bytes), at_(at), end_(end), name_(name) {}

  template <class T>
  T number(const char* what) {
    need(sizeof(T), what);
    T v{};
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  /// A string: its 32-bit length, then its bytes.
  void string(const char* what) { skip(number<std::uint32_t>(what), what); }
  /// The same, returned.
  std::string text(const char* what) {
    const auto n = number<std::uint32_t>(what);
    need(n, what);
    std::string s(bytes_.substr(at_, n));
    at_ += n;
    return s;
  }
  void skip(std::uint64_t n, const char* what) {
    need(n, what);
    at_ += static_cast<std::size_t>(n);
  }
  /// Continues at `to` (at most the end).
  void jump(std::size_t to) { at_ = to < end_ ? to : end_; }
  /// Reads from here on end at `end` (at most the present end, at least here).
  void limit(std::size_t end) { end_ = end < at_ ? at_ : (end < end_ ? end : end_); }
  /// A count of entries that take at least `each` bytes.
  std::uint32_t count(std::size_t each, const char* what) {
    const std::uint32_t n = number<std::uint32_t>(what);
    need(std::uint64_t{n} * each, what);
    return n;
  }
  /// Metadata: a count, then per entry a name, a type name and a sized value.
  void metadata(const char* what) {
    const std::uint32_t n = count(12, what);
    for (std::uint32_t i = 0; i < n; ++i) {
      string(what);
      string(what);
      skip(number<std::uint32_t>(what), what);
    }
  }

 private:
  void need(std::uint64_t n, const char* what) const {
    if (n > end_ - at_)
      throw IoError(name_ + ": the file is corrupt or truncated (its " + what + " runs past the end of " +
                    (end_ == bytes_.size() ? "the file" : "its grid") + ")");
  }

  std::string_view bytes_;
  std::size_t at_, end_;
  const std::string& name_;
};

/// OpenVDB 3.0's file format version: files older than that lay their header out differently.
constexpr std::uint32_t kOldestVersion = 222;

/// The number of 3-vectors of doubles an axis-aligned map of this type stores (OpenVDB's Maps.h), or 0
/// for any other map (the reader refuses those grids anyway, in the child).
int map_vectors(const std::string& type) {
  if (type == "TranslationMap") return 1;
  if (type == "ScaleMap" || type == "UniformScaleMap") return 5;
  if (type == "ScaleTranslateMap" || type == "UniformScaleTranslateMap") return 6;
  return 0;
}

/// The bytes of a float or double grid's stored value (its tree type, "Tree_float_5_4_3" say), or 0.
std::size_t value_bytes(const std::string& tree) {
  if (tree.rfind("Tree_float_", 0) == 0) return 4;
  if (tree.rfind("Tree_double_", 0) == 0) return 8;
  return 0;
}

/// The bytes the topology of one child of the root takes at least: its origin and its two node masks
/// (the tree type's first log2 size: 5 in "Tree_float_5_4_3" is a node of 32^3 voxels, masks of 4 KB).
std::size_t child_bytes(const std::string& tree) {
  const std::size_t at = tree.find('_', tree.find('_') + 1);
  const int log2 = at + 1 < tree.size() ? tree[at + 1] - '0' : 0;
  const std::size_t mask = log2 >= 1 && log2 <= 9 ? (std::size_t{1} << (3 * log2)) / 8 : 0;
  return 3 * sizeof(std::int32_t) + 2 * mask;
}

/// After a grid's transform name (`transform`), of a grid of type `tree`: the map's vectors, then the
/// tree's root node, whose tile and child counts OpenVDB reads one entry at a time whatever is left (a
/// count of a billion in a corrupt file kept it reading a failed stream for 35 s). Only for the maps and
/// value types the reader takes; the others are left to it.
void check_root(Cursor& in, const std::string& transform, const std::string& tree) {
  const int vectors = map_vectors(transform);
  const std::size_t value = value_bytes(tree);
  if (vectors == 0 || value == 0) return;
  in.skip(static_cast<std::uint64_t>(vectors) * 3 * sizeof(double), "transform");
  in.number<std::uint32_t>("tree");  // its buffer count
  in.skip(value, "tree");            // the background value
  const std::uint64_t tiles = in.number<std::uint32_t>("root node");
  const std::uint64_t children = in.number<std::uint32_t>("root node");
  in.skip(tiles * (3 * sizeof(std::int32_t) + value + 1) + children * child_bytes(tree), "root node");
}

}  // namespace

void prescan_vdb(std::string_view bytes, const std::string& name) {
  Cursor c(bytes, 0, bytes.size(), name);
  c.number<std::uint64_t>("header");  // the magic number, checked by the caller
  const auto version = c.number<std::uint32_t>("header");
  if (version < kOldestVersion)
    throw IoError(name + ": file format version " + std::to_string(version) +
                  " predates OpenVDB 3 (222): save it again with a newer OpenVDB");
  c.number<std::uint32_t>("header");  // library major version
  c.number<std::uint32_t>("header");  // library minor version
  const bool offsets =
      c.number<std::uint8_t>("header") != 0;  // a file's grid list has offsets, a stream's not
  c.skip(36, "header");                       // the file's UUID
  c.metadata("file metadata");
  // Then per grid its name, type and offsets, the grid itself right after them.
  const std::uint32_t grids = c.count(36, "list of grids");
  if (!offsets && grids > 1)
    throw IoError(name + ": " + std::to_string(grids) +
                  " grids written as a stream (without grid offsets) are not supported: save them with "
                  "OpenVDB's file writer (openvdb::io::File, pyopenvdb.write)");
  for (std::uint32_t g = 0; g < grids; ++g) {
    c.string("grid name");
    std::string tree = c.text("grid type");
    // An instance shares another grid's tree: it stores none, and its buffers' offset is 0.
    const bool instance = !c.text("grid instance").empty();
    if (instance) tree.clear();
    const auto grid = c.number<std::int64_t>("grid offsets");
    const auto stored_block = c.number<std::int64_t>("grid offsets");
    const auto end = c.number<std::int64_t>("grid offsets");
    const auto block = instance && stored_block == 0 ? end : stored_block;
    if (!offsets) {  // a stream: the first grid follows its name; the next ones only it knows where
      c.number<std::uint32_t>("compression flags");
      c.metadata("grid metadata");
      check_root(c, c.text("transform"), tree);
      return;
    }
    const auto size = static_cast<std::int64_t>(bytes.size());
    if (!(0 <= grid && grid <= block && block <= end && end <= size))
      throw IoError(name + ": the file is corrupt or truncated (grid " + std::to_string(g) +
                    " lies outside the file)");
    // The grid's own header: compression flags, metadata and its transform's type.
    Cursor in(bytes, static_cast<std::size_t>(grid), static_cast<std::size_t>(end), name);
    in.number<std::uint32_t>("compression flags");
    in.metadata("grid metadata");
    const std::string transform = in.text("transform");
    in.limit(static_cast<std::size_t>(block));  // the topology lies before the grid's buffers
    check_root(in, transform, tree);
    c.jump(static_cast<std::size_t>(end));  // the next grid's name follows this grid
  }
}

}  // namespace isopatch::vdb
