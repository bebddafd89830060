// Mesh writers' output in chunks, see byte_sink.hpp.
#include "mesh/byte_sink.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "mesh/io_util.hpp"

namespace isopatch::io {

void ByteSink::check_cancel() const {
  if (cancel_ != nullptr && cancel_->load()) throw LimitError(name_ + ": writing cancelled", "cancel");
}

void ByteSink::spill() {
  largest_held_ = std::max(largest_held_, buffer_.size());
  if (buffer_.empty()) return;
  check_cancel();
  if (consumer_) {
    consumer_(buffer_.data(), buffer_.size());
    buffer_.clear();
    return;
  }
  if (file_ == nullptr) return;
  errno = 0;
  const std::size_t done = std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
  if (done != buffer_.size()) fail(name_, "write failed (" + std::generic_category().message(errno) + ")");
  buffer_.clear();
}

void ByteSink::flush() {
  if (memory_ == nullptr) spill();
}

}  // namespace isopatch::io
