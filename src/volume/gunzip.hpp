#pragma once
// gzip (and zlib) decompression for the NRRD reader, by zlib, bounded: never more than the caller
// expects is inflated, and nothing is allocated for more than the stream could possibly expand to, so a
// small file cannot make the reader allocate or inflate gigabytes.

#include <cstddef>
#include <string>
#include <string_view>

namespace isopatch::volume_io {

/// The decompressed bytes of `compressed` (a gzip or zlib stream), which must be exactly `expected`
/// bytes long. \throw IoError("<name>: ...") for a corrupt stream, or one shorter or longer than that.
std::string gunzip_exactly(std::string_view compressed, std::size_t expected, const std::string& name);

}  // namespace isopatch::volume_io
