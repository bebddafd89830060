// A zip archive written as it comes, see zip_stream.hpp.
#include "mesh/zip_stream.hpp"

#include <isopatch/error.hpp>

#define ZLIB_CONST
#include <zlib.h>

#include <algorithm>
#include <array>
#include <limits>

#include "mesh/io_util.hpp"

namespace isopatch::io {
namespace {

constexpr std::uint16_t kVersion = 45;        // 4.5: Zip64
constexpr std::uint16_t kDataDescriptor = 8;  // general purpose flag bit 3
constexpr std::uint16_t kDeflated = 8;
constexpr std::uint16_t kDosDate = (0U << 9U) | (1U << 5U) | 1U;  // 1980-01-01, the earliest zip date
constexpr std::uint32_t kFull32 = 0xFFFFFFFFU;

/// Compressed output taken from zlib in pieces of this many bytes.
constexpr std::size_t kOutPiece = std::size_t{1} << 16;

template <class T>
void put(ByteSink& out, T value) {
  append_le(out, value);
}

}  // namespace

struct ZipStream::Deflater {
  z_stream stream{};
  bool ready = false;
  std::array<char, kOutPiece> piece{};
};

ZipStream::ZipStream(ByteSink& out) : out_(out), deflater_(std::make_unique<Deflater>()) {}

ZipStream::~ZipStream() {
  if (deflater_->ready) deflateEnd(&deflater_->stream);
}

void ZipStream::begin_entry(const std::string& name) {
  if (open_) throw Error(ErrorKind::Internal, "zip: an entry begun inside another");
  Entry e;
  e.name = name;
  e.offset = out_.written();
  e.crc = static_cast<std::uint32_t>(crc32(0L, Z_NULL, 0));
  entries_.push_back(e);
  // Local file header: sizes and CRC follow in the data descriptor; the Zip64 field says they are 8 bytes.
  put(out_, std::uint32_t{0x04034b50});
  put(out_, kVersion);
  put(out_, kDataDescriptor);
  put(out_, kDeflated);
  put(out_, std::uint16_t{0});  // time
  put(out_, kDosDate);
  put(out_, std::uint32_t{0});  // CRC-32, in the descriptor
  put(out_, kFull32);           // sizes, in the descriptor (Zip64)
  put(out_, kFull32);
  put(out_, static_cast<std::uint16_t>(name.size()));
  put(out_, std::uint16_t{20});  // extra field: the Zip64 one
  out_ += name;
  put(out_, std::uint16_t{0x0001});
  put(out_, std::uint16_t{16});
  put(out_, std::uint64_t{0});
  put(out_, std::uint64_t{0});
  z_stream& z = deflater_->stream;
  z = z_stream{};
  // Raw deflate (no zlib header), level 1: the output keeps up with the disk.
  if (deflateInit2(&z, Z_BEST_SPEED, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw IoError("zip: zlib could not start compressing");
  deflater_->ready = true;
  open_ = true;
}

int ZipStream::deflate_into_sink(int flush) {
  z_stream& z = deflater_->stream;
  z.next_out = reinterpret_cast<Bytef*>(deflater_->piece.data());
  z.avail_out = static_cast<uInt>(kOutPiece);
  const int result = deflate(&z, flush);
  if (result == Z_STREAM_ERROR) throw IoError("zip: zlib failed compressing");
  const std::size_t made = kOutPiece - z.avail_out;
  out_.append(deflater_->piece.data(), made);
  entries_.back().compressed += made;
  return result;
}

void ZipStream::write(const char* data, std::size_t count) {
  if (!open_) throw Error(ErrorKind::Internal, "zip: bytes written outside an entry");
  Entry& e = entries_.back();
  z_stream& z = deflater_->stream;
  while (count > 0) {
    const auto piece = static_cast<uInt>(std::min<std::size_t>(count, std::numeric_limits<uInt>::max() / 2));
    e.crc = static_cast<std::uint32_t>(crc32(e.crc, reinterpret_cast<const Bytef*>(data), piece));
    e.size += piece;
    z.next_in = reinterpret_cast<const Bytef*>(data);
    z.avail_in = piece;
    do deflate_into_sink(Z_NO_FLUSH);
    while (z.avail_out == 0);  // zlib had more than a piece to give
    data += piece;
    count -= piece;
  }
}

void ZipStream::end_entry() {
  if (!open_) throw Error(ErrorKind::Internal, "zip: no entry to end");
  z_stream& z = deflater_->stream;
  z.next_in = nullptr;
  z.avail_in = 0;
  while (deflate_into_sink(Z_FINISH) != Z_STREAM_END) {
  }
  deflateEnd(&z);
  deflater_->ready = false;
  open_ = false;
  const Entry& e = entries_.back();
  put(out_, std::uint32_t{0x08074b50});  // data descriptor, Zip64 sizes
  put(out_, e.crc);
  put(out_, e.compressed);
  put(out_, e.size);
}

void ZipStream::finish() {
  if (open_) throw Error(ErrorKind::Internal, "zip: finished inside an entry");
  const std::uint64_t directory = out_.written();
  for (const Entry& e : entries_) {
    put(out_, std::uint32_t{0x02014b50});
    put(out_, kVersion);  // made by: MS-DOS attributes, 4.5
    put(out_, kVersion);
    put(out_, kDataDescriptor);
    put(out_, kDeflated);
    put(out_, std::uint16_t{0});
    put(out_, kDosDate);
    put(out_, e.crc);
    put(out_, kFull32);  // sizes and offset in the Zip64 field
    put(out_, kFull32);
    put(out_, static_cast<std::uint16_t>(e.name.size()));
    put(out_, std::uint16_t{28});
    put(out_, std::uint16_t{0});  // comment
    put(out_, std::uint16_t{0});  // disk
    put(out_, std::uint16_t{0});  // internal attributes
    put(out_, std::uint32_t{0});  // external attributes
    put(out_, kFull32);
    out_ += e.name;
    put(out_, std::uint16_t{0x0001});
    put(out_, std::uint16_t{24});
    put(out_, e.size);
    put(out_, e.compressed);
    put(out_, e.offset);
  }
  const std::uint64_t end_of_directory = out_.written();
  const std::uint64_t directory_bytes = end_of_directory - directory;
  const auto count = static_cast<std::uint64_t>(entries_.size());
  // Zip64 end of central directory record and its locator.
  put(out_, std::uint32_t{0x06064b50});
  put(out_, std::uint64_t{44});
  put(out_, kVersion);
  put(out_, kVersion);
  put(out_, std::uint32_t{0});
  put(out_, std::uint32_t{0});
  put(out_, count);
  put(out_, count);
  put(out_, directory_bytes);
  put(out_, directory);
  put(out_, std::uint32_t{0x07064b50});
  put(out_, std::uint32_t{0});
  put(out_, end_of_directory);
  put(out_, std::uint32_t{1});
  // End of central directory record, its fields in the Zip64 record where they do not fit.
  const auto small = [](std::uint64_t v, std::uint64_t full) { return v >= full ? full : v; };
  put(out_, std::uint32_t{0x06054b50});
  put(out_, std::uint16_t{0});
  put(out_, std::uint16_t{0});
  put(out_, static_cast<std::uint16_t>(small(count, 0xFFFF)));
  put(out_, static_cast<std::uint16_t>(small(count, 0xFFFF)));
  put(out_, static_cast<std::uint32_t>(small(directory_bytes, kFull32)));
  put(out_, static_cast<std::uint32_t>(small(directory, kFull32)));
  put(out_, std::uint16_t{0});
}

}  // namespace isopatch::io
