// Bounded gzip decompression (gunzip.hpp).
#include "volume/gunzip.hpp"

#include <zlib.h>

#include <algorithm>
#include <climits>

#include "mesh/io_util.hpp"

namespace isopatch::volume_io {

std::string gunzip_exactly(std::string_view compressed, std::size_t expected, const std::string& name) {
  // Deflate expands at most 1032-fold (a 258-byte match per 2 bits): a header asking for more than that
  // is refused before anything is allocated.
  if (expected / 1032 > compressed.size() + 64)
    io::fail(name, "the gzip data (" + std::to_string(compressed.size()) + " bytes) cannot hold the " +
                       std::to_string(expected) + " bytes the header declares");
  z_stream z{};
  // 15 + 32: the largest window, and the header (gzip or zlib) detected from the stream.
  if (inflateInit2(&z, 15 + 32) != Z_OK) io::fail(name, "cannot start gzip decompression");
  std::string out(expected, '\0');
  std::size_t in_pos = 0, out_pos = 0;
  int status = Z_OK;
  char spare = 0;  // room for one byte beyond `expected`: a stream that would write it is too long
  while (status == Z_OK) {
    const std::size_t in_chunk = std::min<std::size_t>(compressed.size() - in_pos, UINT_MAX);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + in_pos));
    z.avail_in = static_cast<uInt>(in_chunk);
    const bool full = out_pos == expected;
    const std::size_t out_chunk = full ? 1 : std::min<std::size_t>(expected - out_pos, UINT_MAX);
    z.next_out = reinterpret_cast<Bytef*>(full ? &spare : out.data() + out_pos);
    z.avail_out = static_cast<uInt>(out_chunk);
    status = inflate(&z, Z_NO_FLUSH);
    in_pos += in_chunk - z.avail_in;
    const std::size_t written = out_chunk - z.avail_out;
    if (full && written > 0) {
      inflateEnd(&z);
      io::fail(name, "the gzip data holds more than the " + std::to_string(expected) +
                         " bytes the header declares");
    }
    out_pos += written;
    if (status == Z_BUF_ERROR && in_pos == compressed.size()) break;  // input exhausted
    if (status == Z_BUF_ERROR) status = Z_OK;
  }
  inflateEnd(&z);
  if (status != Z_STREAM_END) {
    if (status == Z_OK || status == Z_BUF_ERROR)
      io::fail(name, "the gzip data is truncated (" + std::to_string(out_pos) + " of " +
                         std::to_string(expected) + " bytes)");
    io::fail(name, "the gzip data is corrupt");
  }
  if (out_pos != expected)
    io::fail(name, "the gzip data holds " + std::to_string(out_pos) + " bytes, the header declares " +
                       std::to_string(expected));
  return out;
}

}  // namespace isopatch::volume_io
