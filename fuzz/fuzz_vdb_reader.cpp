// libFuzzer target: OpenVDB files (.vdb) as surfaces. The input is the file; decode_vdb_surface must
// return a surface or throw an isopatch Error (IoError, InputError, NoSurfaceError) with a one-line
// message naming the file. A surface it returns is evaluated and bounded at a few points of its box:
// values must not crash, bounds must hold the values at their box's centre.
//
// OpenVDB allocates what a file declares (a compressed block's size) before reading it. Without ASan
// an absurd size throws std::bad_alloc, which the reader turns into an IoError; ASan's allocator aborts
// instead. The replacement operators below give this target the plain process's behaviour: above
// kLargest bytes new throws, below it memory comes from malloc (which ASan still checks).
//
// The library reads a grid's tree in a forked child (src/vdb/isolated_read.hpp), whose crash on a hostile
// file is an IoError here. The child inherits libFuzzer's crash handlers, which would save its input as
// a crash of this target: a fork handler takes them off in the child, so it dies quietly.
#include <pthread.h>
#include <sanitizer/common_interface_defs.h>
#include <isopatch/error.hpp>
#include <isopatch/vdb_surface.hpp>

#include <cmath>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string>
#include <string_view>

namespace {
constexpr std::size_t kLargest = std::size_t{1} << 30;
void* allocate(std::size_t n, std::size_t alignment = 0) {
  if (n > kLargest) throw std::bad_alloc();
  n = n == 0 ? 1 : n;
  void* p = alignment > alignof(std::max_align_t)
                ? std::aligned_alloc(alignment, (n + alignment - 1) / alignment * alignment)
                : std::malloc(n);
  if (!p) throw std::bad_alloc();
  return p;
}
void* allocate_or_null(std::size_t n, std::size_t alignment = 0) noexcept {
  try {
    return allocate(n, alignment);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
/// In a forked child: no death callback (libFuzzer's saves the input), default signal actions.
void quiet_child() {
  __sanitizer_set_death_callback(nullptr);
  for (const int s : {SIGSEGV, SIGBUS, SIGABRT, SIGILL, SIGFPE}) std::signal(s, SIG_DFL);
}
const int kQuietChildren = pthread_atfork(nullptr, nullptr, quiet_child);
}  // namespace

// Every form of the replaceable global operators, so that no allocation pairs one of ours with ASan's.
void* operator new(std::size_t n) {
  return allocate(n);
}
void* operator new[](std::size_t n) {
  return allocate(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return allocate_or_null(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return allocate_or_null(n);
}
void* operator new(std::size_t n, std::align_val_t a) {
  return allocate(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return allocate(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate_or_null(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return allocate_or_null(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const isopatch::SurfacePtr s = isopatch::decode_vdb_surface(bytes, {}, "fuzz.vdb");
    const isopatch::Box& box = s->box();
    for (int k = 0; k <= 4; ++k) {
      const isopatch::Vec3 p = box.lo + (box.hi - box.lo) * (k / 4.0);
      const double v = s->value(p);
      s->second_order(p);
      const isopatch::Vec3 half = (box.hi - box.lo) * (0.05 * (k + 1));
      const auto bound = s->bound(isopatch::Box{p - half, p + half});
      if (std::isfinite(v) && bound && !bound->contains(v)) std::abort();
    }
  } catch (const isopatch::Error& e) {
    const std::string message = e.what();
    if (message.find("fuzz.vdb") == std::string::npos || message.find('\n') != std::string::npos)
      std::abort();
  }
  return 0;
}
