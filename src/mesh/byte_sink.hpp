#pragma once
// Where a mesh writer's bytes go (internal): a file (or a consumer such as a compressor), in chunks as
// they come, so that writing a mesh holds at most one chunk besides the mesh; or a string in memory
// (encode_mesh). Writers append with the few members of std::string they use, so number formatting
// (io_util.hpp) serves both.

#include <atomic>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace isopatch::io {

class ByteSink {
 public:
  /// A file sink hands its bytes to the file when it holds this many.
  static constexpr std::size_t kChunk = std::size_t{1} << 20;

  /// Appends to `memory`.
  explicit ByteSink(std::string& memory) : memory_(&memory) {}
  /// Hands its bytes in chunks to `consumer` (a compressor, ...).
  explicit ByteSink(std::function<void(const char*, std::size_t)> consumer) : consumer_(std::move(consumer)) {
    buffer_.reserve(kChunk);
  }
  /// Writes to `file` (open for writing, owned by the caller); `name` is the file's name in errors.
  ByteSink(std::FILE* file, std::string name) : file_(file), name_(std::move(name)) {
    buffer_.reserve(kChunk);
  }
  ByteSink(const ByteSink&) = delete;
  ByteSink& operator=(const ByteSink&) = delete;

  void append(const char* data, std::size_t count) {
    std::string& to = memory_ != nullptr ? *memory_ : buffer_;
    to.append(data, count);
    if (memory_ == nullptr && buffer_.size() >= kChunk) spill();
    written_ += count;
  }
  void append(const char* first, const char* last) { append(first, static_cast<std::size_t>(last - first)); }
  ByteSink& operator+=(std::string_view text) {
    append(text.data(), text.size());
    return *this;
  }
  ByteSink& operator+=(char c) {
    append(&c, 1);
    return *this;
  }

  /// Hands what it holds to the file. \throw IoError when the write fails (disk full, ...);
  /// LimitError("cancel") when the flag given to stop_when() is set.
  void flush();
  /// A file or consumer sink checks `cancel` (if not null) before it hands each chunk on and throws
  /// LimitError("cancel") once it is true; `cancel` must outlive the sink.
  void stop_when(const std::atomic<bool>* cancel) { cancel_ = cancel; }
  /// \throw LimitError("cancel") naming the file when the flag given to stop_when() is set.
  void check_cancel() const;
  /// Bytes appended so far.
  std::size_t written() const { return written_; }
  /// The most bytes a file sink held at once (at most kChunk plus the largest single append): what a
  /// writer adds to the mesh in memory.
  std::size_t largest_held() const { return largest_held_; }

 private:
  void spill();

  std::string* memory_ = nullptr;
  std::FILE* file_ = nullptr;
  const std::atomic<bool>* cancel_ = nullptr;
  std::function<void(const char*, std::size_t)> consumer_;
  std::string name_;
  std::string buffer_;
  std::size_t written_ = 0;
  std::size_t largest_held_ = 0;
};

}  // namespace isopatch::io
