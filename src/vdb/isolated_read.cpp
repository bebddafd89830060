// OpenVDB's reading in a child process (isolated_read.hpp).
#include "vdb/isolated_read.hpp"

#include <isopatch/error.hpp>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace isopatch::vdb {

namespace {

/// Appends plain numbers and strings to a byte string.
struct Writer {
  std::string out;
  template <class T>
  void put(const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void put_text(const std::string& s) {
    put<std::uint64_t>(s.size());
    out += s;
  }
};

/// Reads them back, refusing anything past the end.
struct Reader {
  std::string_view in;
  bool ok = true;
  template <class T>
  T get() {
    T v{};
    if (in.size() < sizeof(T)) {
      ok = false;
      return v;
    }
    std::memcpy(&v, in.data(), sizeof(T));
    in.remove_prefix(sizeof(T));
    return v;
  }
  std::string get_text() {
    const auto n = get<std::uint64_t>();
    if (!ok || n > in.size()) {
      ok = false;
      return {};
    }
    std::string s(in.substr(0, static_cast<std::size_t>(n)));
    in.remove_prefix(static_cast<std::size_t>(n));
    return s;
  }
};

constexpr char kSamples = 'S', kInputError = 'I', kIoError = 'O';

std::string encode(const SparseSamples& s, const std::string& chosen) {
  Writer w;
  w.put(kSamples);
  w.put_text(chosen);
  for (int a = 0; a < 3; ++a) w.put(s.spacing[a]);
  for (int a = 0; a < 3; ++a) w.put(s.origin[a]);
  w.put(s.tiles.background);
  for (const auto v : s.active_lo) w.put(v);
  for (const auto v : s.active_hi) w.put(v);
  w.put(s.active_voxels);
  w.put<std::uint64_t>(s.leaves.size());
  for (const auto& [key, values] : s.leaves) {
    for (const auto v : key) w.put(v);
    w.out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  }
  w.put<std::uint64_t>(s.tiles.levels.size());
  for (const auto& [shift, level] : s.tiles.levels) {
    w.put(shift);
    w.put<std::uint64_t>(level.size());
    for (const auto& [key, value] : level) {
      for (const auto v : key) w.put(v);
      w.put(value);
    }
  }
  return w.out;
}

/// An error's kind, setting and message; the message kept to one line of at most 300 characters (a
/// corrupt file's names can be long or hold line breaks).
std::string encode_error(char kind, const std::string& setting, std::string message) {
  constexpr std::size_t kLongest = 300;
  if (message.size() > kLongest) message = message.substr(0, kLongest) + "...";
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  Writer w;
  w.put(kind);
  w.put_text(setting);
  w.put_text(message);
  return w.out;
}

[[noreturn]] void malformed(const std::string& name) {
  throw IoError(name + ": the file is corrupt: OpenVDB failed reading it (a malformed answer)");
}

SparseSamples decode(std::string_view bytes, std::string& chosen, const std::string& name) {
  Reader r{bytes};
  const char kind = r.get<char>();
  if (kind == kInputError || kind == kIoError) {
    const std::string setting = r.get_text(), message = r.get_text();
    if (!r.ok) malformed(name);
    if (kind == kInputError) throw InputError(message, setting);
    throw IoError(message);
  }
  if (kind != kSamples) malformed(name);
  SparseSamples s;
  chosen = r.get_text();
  for (int a = 0; a < 3; ++a) s.spacing[a] = r.get<double>();
  for (int a = 0; a < 3; ++a) s.origin[a] = r.get<double>();
  s.tiles.background = r.get<double>();
  for (auto& v : s.active_lo) v = r.get<std::int64_t>();
  for (auto& v : s.active_hi) v = r.get<std::int64_t>();
  s.active_voxels = r.get<std::uint64_t>();
  const auto leaves = r.get<std::uint64_t>();
  constexpr std::size_t kLeafBytes = 3 * sizeof(std::int64_t) + kBrickVoxels * sizeof(double);
  if (!r.ok || leaves > r.in.size() / kLeafBytes) malformed(name);
  for (std::uint64_t i = 0; i < leaves; ++i) {
    Coord key{r.get<std::int64_t>(), r.get<std::int64_t>(), r.get<std::int64_t>()};
    std::vector<double> values(kBrickVoxels);
    for (double& v : values) v = r.get<double>();
    s.leaves.emplace(key, std::move(values));
  }
  const auto levels = r.get<std::uint64_t>();
  if (!r.ok || levels > 64) malformed(name);
  for (std::uint64_t l = 0; l < levels; ++l) {
    const int shift = r.get<int>();
    const auto count = r.get<std::uint64_t>();
    if (!r.ok || count > r.in.size() / (4 * sizeof(double))) malformed(name);
    auto& level = s.tiles.levels[shift];
    for (std::uint64_t i = 0; i < count; ++i) {
      Coord key{r.get<std::int64_t>(), r.get<std::int64_t>(), r.get<std::int64_t>()};
      level[key] = r.get<double>();
    }
  }
  if (!r.ok || !r.in.empty()) malformed(name);
  return s;
}

void write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nothing to tell
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

/// The child's answer, read until it closes the pipe; false when `wall_seconds` pass first.
bool read_all(int fd, double wall_seconds, std::string& out) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wall_seconds);
  char buffer[1 << 16];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<std::int64_t>(left.count(), 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return true;  // nothing more to read: the answer is judged as it is
    if (ready == 0) continue;
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    out.append(buffer, static_cast<std::size_t>(n));
  }
}

std::string describe(int status) {
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) return "it ran out of its processor time";
  if (WIFSIGNALED(status)) return "it stopped on signal " + std::to_string(WTERMSIG(status));
  if (WIFEXITED(status)) return "it exited with status " + std::to_string(WEXITSTATUS(status));
  return "it stopped";
}

}  // namespace

int reading_seconds(std::size_t file_bytes) {
  constexpr double kMinimum = 2.0, kPerMegabyte = 10.0;
  return static_cast<int>(std::ceil(kMinimum + kPerMegabyte * static_cast<double>(file_bytes) / 1e6));
}

SparseSamples read_in_child(const std::string& name, int cpu_seconds, std::string& chosen,
                            const std::function<SparseSamples(std::string&)>& read) {
  const int seconds = std::max(cpu_seconds, 1);
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw IoError(name + ": cannot start a process to read the file");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw IoError(name + ": cannot start a process to read the file");
  }
  if (pid == 0) {  // the child: read, answer, and leave without running any exit handler
    ::close(fds[0]);
    // What a corrupted heap prints as it aborts (glibc, a sanitizer) is not the user's: the parent
    // reports the failure in one line.
    if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    // A hostile file can hold OpenVDB in a loop for long (one of 80 KB read from a stream that had
    // already failed, count after count, for 35 s; found by fuzz_vdb_reader): the kernel stops the
    // child at its limit.
    const rlimit cpu{static_cast<rlim_t>(seconds), static_cast<rlim_t>(seconds) + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
    std::string answer;
    try {
      std::string grid;
      const SparseSamples samples = read(grid);
      answer = encode(samples, grid);
    } catch (const InputError& e) {
      answer = encode_error(kInputError, e.setting(), e.what());
    } catch (const std::exception& e) {
      answer = encode_error(kIoError, "", e.what());
    } catch (...) {
      answer = encode_error(kIoError, "", name + ": not a readable OpenVDB file");
    }
    write_all(fds[1], answer);
    ::_exit(0);
  }
  ::close(fds[1]);
  // The wall clock bounds a child that waits instead of computing (a lock held across the fork).
  std::string answer;
  const bool answered = read_all(fds[0], 4.0 * seconds, answer);
  ::close(fds[0]);
  if (!answered) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw IoError(name + ": lost the process reading the file");
  }
  if (!answered || (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU))
    throw IoError(name + ": the file is corrupt: OpenVDB did not finish reading it in " +
                  std::to_string(answered ? seconds : 4 * seconds) + " s" +
                  (answered ? " of processor time" : ""));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw IoError(name + ": the file is corrupt: OpenVDB failed reading it (" + describe(status) + ")");
  return decode(answer, chosen, name);
}

}  // namespace isopatch::vdb
