#pragma once
// A file mapped read-only into memory (POSIX mmap): the pages a reader touches are loaded by the
// operating system, so a process that reads a small part of a huge file holds only that part.

#include <cstddef>
#include <string>
#include <string_view>

namespace isopatch::volume_io {

class MappedFile {
 public:
  /// Maps the whole of `path` read-only.
  /// \throw IoError("<path>: cannot open: <reason>") when it cannot be opened, is not a regular file,
  ///        is empty or cannot be mapped.
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  /// The file's bytes; valid while this object lives.
  std::string_view bytes() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace isopatch::volume_io
