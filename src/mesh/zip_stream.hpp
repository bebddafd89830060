#pragma once
// A zip archive written entry by entry as its bytes come (internal; the container of 3MF packages):
// each entry raw-deflated by zlib, followed by a data descriptor (its CRC-32 and sizes are known only
// at its end), Zip64 sizes and offsets throughout (as lib3mf writes them, so readers of 3MF accept
// them, and no entry or archive is limited to 4 GiB), and fixed dates: the same content gives the same
// bytes. Follows PKWARE's APPNOTE.TXT 6.3 (local file header, data descriptor, central directory,
// Zip64 end of central directory record and locator, end of central directory record).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesh/byte_sink.hpp"

namespace isopatch::io {

class ZipStream {
 public:
  /// Writes the archive to `out`, which must outlive it.
  explicit ZipStream(ByteSink& out);
  ~ZipStream();
  ZipStream(const ZipStream&) = delete;
  ZipStream& operator=(const ZipStream&) = delete;

  /// Starts an entry named `name` (a path with '/' separators). \pre no entry is open.
  void begin_entry(const std::string& name);
  /// Compresses `count` bytes of the open entry; compressed bytes go to the sink as zlib gives them.
  void write(const char* data, std::size_t count);
  /// Ends the open entry (its data descriptor).
  void end_entry();
  /// Writes the central directory and the end records. \pre no entry is open.
  void finish();

 private:
  struct Entry {
    std::string name;
    std::uint64_t offset = 0, compressed = 0, size = 0;
    std::uint32_t crc = 0;
  };
  /// One call of zlib's deflate with `flush`, its output to the sink; zlib's result.
  int deflate_into_sink(int flush);

  ByteSink& out_;
  struct Deflater;
  std::unique_ptr<Deflater> deflater_;
  std::vector<Entry> entries_;
  bool open_ = false;
};

}  // namespace isopatch::io
