// Shared machinery of the mesh readers and writers. Files are read whole with stdio (one allocation,
// no per-line stream overhead) and written in chunks (byte_sink.hpp); a failed write is seen at the
// chunk's fwrite or at fclose, and the partial file removed.
#include "mesh/io_util.hpp"

#include "mesh/byte_sink.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include <unistd.h>

namespace isopatch::io {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}
bool is_line_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string reason(int error) {
  return std::generic_category().message(error);
}

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};

template <class Int>
bool parse_integer(std::string_view token, Int& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;  // from_chars itself rejects '-' for unsigned
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, out);
  return ec == std::errc{} && ptr == end;
}

}  // namespace

std::string load_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a mesh file");
  errno = 0;
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail(path, "cannot open for reading (" + reason(errno) + ")");
  std::string bytes;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec) bytes.reserve(static_cast<std::size_t>(size));
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) bytes.append(chunk, got);
  if (std::ferror(file.get())) fail(path, "read failed (" + reason(errno) + ")");
  return bytes;
}

namespace {

/// The temporary files of writes in progress, for remove_unfinished_files() from a signal handler: fixed
/// slots of fixed buffers (no allocation there), claimed and released with atomics.
constexpr std::size_t kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
struct UnfinishedSlot {
  std::atomic<bool> used{false};
  std::atomic<bool> ready{false};
  char path[kPathBytes] = {};
};
std::array<UnfinishedSlot, kSlots> unfinished;

/// Holds a temporary file's name in a slot while it is written (none free: not listed, still removed
/// on errors).
class UnfinishedFile {
 public:
  explicit UnfinishedFile(const std::string& path) {
    if (path.size() >= kPathBytes) return;
    for (UnfinishedSlot& s : unfinished) {
      bool expected = false;
      if (s.used.compare_exchange_strong(expected, true)) {
        std::memcpy(s.path, path.c_str(), path.size() + 1);
        s.ready.store(true);
        slot_ = &s;
        return;
      }
    }
  }
  ~UnfinishedFile() {
    if (slot_ == nullptr) return;
    slot_->ready.store(false);
    slot_->used.store(false);
  }
  UnfinishedFile(const UnfinishedFile&) = delete;
  UnfinishedFile& operator=(const UnfinishedFile&) = delete;

 private:
  UnfinishedSlot* slot_ = nullptr;
};

/// Removes a temporary file (errors ignored: it may not exist yet).
void remove_temporary(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

/// Opens `file_path`, lets `write` fill it through a ByteSink (errors name `path`) and closes it; a
/// temporary file is removed when anything fails.
void fill(const std::string& path, const std::string& file_path, bool temporary,
          const std::function<void(ByteSink&)>& write, const std::atomic<bool>* cancel) {
  errno = 0;
  std::FILE* file = std::fopen(file_path.c_str(), "wb");
  if (!file) {
    const int why = errno;
    const std::filesystem::path folder = std::filesystem::path(file_path).parent_path();
    std::error_code ignored;
    if (temporary && !folder.empty() && !std::filesystem::is_directory(folder, ignored))
      fail(path, "cannot write: the folder '" + folder.string() + "' does not exist");
    fail(path,
         (temporary ? "cannot write in its folder (" : "cannot open for writing (") + reason(why) + ")");
  }
  try {
    ByteSink out(file, path);
    out.stop_when(cancel);
    write(out);
    out.flush();
    out.check_cancel();  // a mesh of one chunk, or a cancel during its last write
  } catch (...) {
    std::fclose(file);
    if (temporary) remove_temporary(file_path);
    throw;
  }
  errno = 0;
  if (std::fclose(file) != 0) {
    const int why = errno;
    if (temporary) remove_temporary(file_path);
    fail(path, "write failed when closing (" + reason(why) + ")");
  }
}

/// Writes of this process so far: the temporary files of two writes at once never share a name.
std::atomic<std::uint64_t> writes{0};

}  // namespace

void write_file(const std::string& path, const std::function<void(ByteSink&)>& write,
                const std::atomic<bool>* cancel) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // through symbolic links
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    if (fs::is_directory(status)) fail(path, "is a folder, not a file");
    return fill(path, path, false, write, cancel);  // a device or a pipe: written directly
  }
  // Beside the file a link points to, so that the rename replaces that file and the link stays.
  fs::path target = path;
  if (fs::is_symlink(fs::symlink_status(path, error))) {
    const fs::path resolved = fs::weakly_canonical(path, error);
    if (!error) target = resolved;
  }
  // Hidden, and named after the file, the process and the write (appended: GCC 12 warns wrongly about
  // "literal" + std::string).
  std::string name = ".";
  name += target.filename().string();
  name += ".isopatch-";
  name += std::to_string(::getpid());
  name += "-";
  name += std::to_string(writes.fetch_add(1));
  name += ".part";
  const std::string temporary =
      (target.has_parent_path() ? target.parent_path() / name : fs::path(name)).string();
  const UnfinishedFile listed(temporary);
  fill(path, temporary, true, write, cancel);
  errno = 0;
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const int why = errno;
    remove_temporary(temporary);
    fail(path, "cannot replace the file (" + reason(why) + ")");
  }
}

void remove_unfinished() noexcept {
  for (UnfinishedSlot& s : unfinished)
    if (s.ready.load()) ::unlink(s.path);
}

void fail(const std::string& name, const std::string& problem) {
  throw IoError(name + ": " + problem);
}

void fail_at(const std::string& name, std::size_t line, const std::string& problem) {
  throw IoError(name + ":" + std::to_string(line) + ": " + problem);
}

std::string_view Tokens::next() {
  while (pos_ < text_.size() && is_space(text_[pos_])) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

std::string_view Tokens::next_on_line(char comment) {
  while (pos_ < text_.size() && is_line_space(text_[pos_])) ++pos_;
  if (pos_ < text_.size() && comment != '\0' && text_[pos_] == comment) {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

bool Tokens::next_line() {
  const std::size_t newline = text_.find('\n', pos_);
  if (newline == std::string_view::npos) {
    pos_ = text_.size();
    return false;
  }
  pos_ = newline + 1;
  ++line_;
  return pos_ < text_.size();
}

bool Tokens::at_end() {
  while (pos_ < text_.size() && is_space(text_[pos_])) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  return pos_ == text_.size();
}

bool parse_double(std::string_view token, double& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, out, std::chars_format::general);
  return ec == std::errc{} && ptr == end;
}

bool parse_int(std::string_view token, std::int64_t& out) {
  return parse_integer(token, out);
}
bool parse_uint(std::string_view token, std::uint64_t& out) {
  return parse_integer(token, out);
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 32;
  std::string text = "'";
  for (char c : token.substr(0, kShown)) text += (c >= 32 && c < 127) ? c : '?';
  if (token.size() > kShown) text += "...";
  return text + "'";
}

std::string add_polygon(Mesh& mesh, std::span<const std::int64_t> corners, std::size_t vertex_count) {
  const std::size_t n = corners.size();
  if (n < 3) return "has " + std::to_string(n) + " vertices (at least 3 needed)";
  if (n > kMaxPolygon)
    return "has " + std::to_string(n) + " vertices (more than " + std::to_string(kMaxPolygon) + ")";
  for (std::int64_t c : corners)
    if (c < 0 || static_cast<std::uint64_t>(c) >= vertex_count)
      return "refers to vertex " + std::to_string(c) + " but there are " + std::to_string(vertex_count) +
             " vertices";
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const Triangle t{static_cast<std::uint32_t>(corners[0]), static_cast<std::uint32_t>(corners[i]),
                     static_cast<std::uint32_t>(corners[i + 1])};
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      const std::uint32_t v = (t[0] == t[1] || t[0] == t[2]) ? t[0] : t[1];
      return "repeats vertex " + std::to_string(v) + " (degenerate)";
    }
    mesh.triangles.push_back(t);
  }
  return {};
}

void check_read_mesh(const Mesh& mesh, const std::string& name) {
  try {
    mesh.validate();
  } catch (const InputError& e) {
    fail(name, e.what());
  }
}

}  // namespace isopatch::io
