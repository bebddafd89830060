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
  void skip(std::uint64_t n, const char* what) {
    need(n, what);
    at_ += static_cast<std::size_t>(n);
  }
  /// Continues at `to` (at most the end).
  void jump(std::size_t to) { at_ = to < end_ ? to : end_; }
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
    c.string("grid type");
    c.string("grid instance");
    const auto grid = c.number<std::int64_t>("grid offsets");
    const auto block = c.number<std::int64_t>("grid offsets");
    const auto end = c.number<std::int64_t>("grid offsets");
    if (!offsets) {  // a stream: the first grid follows its name; the next ones only it knows where
      c.number<std::uint32_t>("compression flags");
      c.metadata("grid metadata");
      c.string("transform");
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
    in.string("transform");
    c.jump(static_cast<std::size_t>(end));  // the next grid's name follows this grid
  }
}

}  // namespace isopatch::vdb
