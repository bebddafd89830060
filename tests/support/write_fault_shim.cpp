// A preloaded library (LD_PRELOAD) that makes file writes fail or stall, for the tests of writes that
// are whole or not at all (python/tests/test_interrupted_writes.py): a full disk without mounting one,
// and a process held in the middle of writing a file so that a test can interrupt it there. Only files
// opened for writing whose path contains ISOPATCH_SHIM_MATCH are touched:
//   ISOPATCH_SHIM_FAIL_AFTER=N  the bytes past the first N of such a file fail with ENOSPC;
//   ISOPATCH_SHIM_STALL=PATH    each write to such a file creates PATH and waits while it exists (60 s
//                               at most): a test removes it to let the write go on.
#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

using FopenFn = FILE* (*)(const char*, const char*);
using FwriteFn = size_t (*)(const void*, size_t, size_t, FILE*);

std::atomic<FILE*> watched{nullptr};
std::atomic<unsigned long long> written{0};

bool matches(const char* path, const char* mode) {
  const char* pattern = std::getenv("ISOPATCH_SHIM_MATCH");
  return pattern != nullptr && *pattern != '\0' && path != nullptr && std::strchr(mode, 'w') != nullptr &&
         std::strstr(path, pattern) != nullptr;
}

FILE* open_and_watch(FopenFn real, const char* path, const char* mode) {
  FILE* file = real(path, mode);
  if (file != nullptr && matches(path, mode)) {
    watched.store(file);
    written.store(0);
  }
  return file;
}

}  // namespace

extern "C" FILE* fopen(const char* path, const char* mode) {
  static const auto real = reinterpret_cast<FopenFn>(dlsym(RTLD_NEXT, "fopen"));
  return open_and_watch(real, path, mode);
}

extern "C" FILE* fopen64(const char* path, const char* mode) {
  static const auto real = reinterpret_cast<FopenFn>(dlsym(RTLD_NEXT, "fopen64"));
  return open_and_watch(real, path, mode);
}

extern "C" size_t fwrite(const void* data, size_t size, size_t count, FILE* file) {
  static const auto real = reinterpret_cast<FwriteFn>(dlsym(RTLD_NEXT, "fwrite"));
  if (file != watched.load() || size == 0) return real(data, size, count, file);
  if (const char* mark = std::getenv("ISOPATCH_SHIM_STALL"); mark != nullptr && *mark != '\0') {
    if (FILE* m = std::fopen(mark, "w")) std::fclose(m);
    // Held while the mark exists (the test removes it to let the write go on), at most 60 s.
    for (int step = 0; step < 3000 && ::access(mark, F_OK) == 0; ++step) ::usleep(20000);
  }
  if (const char* limit = std::getenv("ISOPATCH_SHIM_FAIL_AFTER"); limit != nullptr && *limit != '\0') {
    const unsigned long long room = std::strtoull(limit, nullptr, 10);
    const unsigned long long so_far = written.load();
    const unsigned long long bytes = static_cast<unsigned long long>(size) * count;
    if (so_far + bytes > room) {
      const size_t fits = so_far >= room ? 0 : static_cast<size_t>((room - so_far) / size);
      const size_t done = fits > 0 ? real(data, size, fits, file) : 0;
      written.fetch_add(static_cast<unsigned long long>(done) * size);
      errno = ENOSPC;
      return done;
    }
  }
  const size_t done = real(data, size, count, file);
  written.fetch_add(static_cast<unsigned long long>(done) * size);
  return done;
}
