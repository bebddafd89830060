#pragma once
// Internal helpers shared by the mesh readers and writers (not installed): whole-file load and save,
// a whitespace tokenizer that counts lines, strict number parsing and formatting, binary scalars of
// either byte order, and the checks every reader applies to faces. Every reader works on the whole
// file held in memory, so "how many bytes are left" is always known before anything is allocated.

#include <isopatch/error.hpp>
#include <isopatch/mesh.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

namespace isopatch::io {

/// The largest polygon any reader accepts (a larger count is taken as a lie of the file).
constexpr std::size_t kMaxPolygon = 1000;

/// The whole content of `path`. \throw IoError when it cannot be opened or read.
std::string load_file(const std::string& path);
class ByteSink;
/// Lets `write` write `path` through a ByteSink in chunks, whole or not at all: into a temporary file
/// beside it, renamed onto it at the end (mesh_io.hpp's write_whole_file says the rest). A write that
/// throws leaves no temporary file and the old file at `path` as it was.
/// With `cancel` (may be null) set before the rename, the write stops at the next chunk or at the end
/// with LimitError("cancel"), as any other failure.
/// \throw IoError when the file cannot be created or the write fails (disk full, ...); what `write`
/// throws; LimitError on cancel.
void write_file(const std::string& path, const std::function<void(ByteSink&)>& write,
                const std::atomic<bool>* cancel = nullptr);
/// Unlinks the temporary files of the writes in progress (mesh_io.hpp's remove_unfinished_files).
void remove_unfinished() noexcept;

/// Throws IoError("<name>: <problem>").
[[noreturn]] void fail(const std::string& name, const std::string& problem);
/// Throws IoError("<name>:<line>: <problem>").
[[noreturn]] void fail_at(const std::string& name, std::size_t line, const std::string& problem);

/// Whitespace-separated tokens of a text, with the line number of the last token returned.
class Tokens {
 public:
  explicit Tokens(std::string_view text, std::size_t first_line = 1) : text_(text), line_(first_line) {}

  /// The next token anywhere; empty at the end of the text.
  std::string_view next();
  /// The next token on the current line; empty at the end of the line (the newline stays unread).
  /// A token starting with `comment` (if not '\0') ends the line: the rest of it is skipped.
  std::string_view next_on_line(char comment = '\0');
  /// Skips the rest of the current line and its newline; false at the end of the text.
  bool next_line();
  /// True when only whitespace is left.
  bool at_end();

  std::size_t line() const { return line_; }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

/// Strict parsers: the whole token must be the number (an optional leading '+' is allowed).
bool parse_double(std::string_view token, double& out);
bool parse_int(std::string_view token, std::int64_t& out);
bool parse_uint(std::string_view token, std::uint64_t& out);

/// A token shortened for an error message, in quotes.
std::string quoted(std::string_view token);

/// Shortest decimal text that reads back to exactly the same value (doubles, floats), or the integer;
/// to a std::string or a ByteSink.
template <class Out, class T>
void append_number(Out& out, T value) {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, float> || std::is_same_v<T, std::int64_t>);
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, static_cast<std::size_t>(result.ptr - buffer));
}

/// Bytes of a scalar in little-endian order, to a std::string or a ByteSink.
template <class Out, class T>
void append_le(Out& out, T value) {
  auto bytes = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if constexpr (std::endian::native == std::endian::big) std::ranges::reverse(bytes);
  out.append(bytes.data(), bytes.size());
}

/// A scalar stored at `p` in little-endian (big_endian = false) or big-endian order.
template <class T>
T load_scalar(const char* p, bool big_endian) {
  std::array<char, sizeof(T)> bytes;
  std::memcpy(bytes.data(), p, sizeof(T));
  if (big_endian != (std::endian::native == std::endian::big)) std::ranges::reverse(bytes);
  return std::bit_cast<T>(bytes);
}

/// Appends the fan triangulation (c0, ci, ci+1) of a polygon whose corners are 0-based indices.
/// Returns an empty string on success, else the problem ("has 2 vertices", "refers to vertex 9 but
/// there are 4 vertices", "repeats vertex 3") for the caller to prefix with the face it read.
std::string add_polygon(Mesh& mesh, std::span<const std::int64_t> corners, std::size_t vertex_count);

/// Final safety net of every reader: Mesh::validate(), with its InputError turned into an IoError.
void check_read_mesh(const Mesh& mesh, const std::string& name);

}  // namespace isopatch::io
