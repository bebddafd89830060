// openvdb_functions (openvdb_loader.hpp).
#include "vdb/openvdb_loader.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include <dlfcn.h>

namespace isopatch::vdb {

#ifdef ISOPATCH_OPENVDB_LINKED

const OpenVdbFunctions& openvdb_functions() {
  static std::once_flag once;
  const OpenVdbFunctions* functions = isopatch_openvdb_functions();
  std::call_once(once, [functions] { functions->initialize(); });
  return *functions;
}

#else

namespace {

constexpr const char* kPluginName = "isopatch_openvdb.so";

/// Where to look, most specific first (openvdb_loader.hpp).
std::vector<std::filesystem::path> candidates() {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  if (const char* path = std::getenv("ISOPATCH_OPENVDB_PLUGIN"); path != nullptr && *path != '\0')
    out.emplace_back(path);
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(&candidates), &info) != 0 && info.dli_fname != nullptr) {
    std::error_code ec;
    const fs::path self = fs::canonical(fs::path(info.dli_fname), ec);
    if (!ec) {
      out.push_back(self.parent_path() / kPluginName);
      out.push_back(self.parent_path().parent_path() / ISOPATCH_LIBDIR / "isopatch" / kPluginName);
    }
  }
  out.push_back(fs::path(ISOPATCH_OPENVDB_INSTALLED) / kPluginName);
  out.push_back(fs::path(ISOPATCH_OPENVDB_BUILT) / kPluginName);
  std::vector<fs::path> unique;  // each place once, in this order
  for (fs::path& path : out) {
    path = path.lexically_normal();
    if (std::find(unique.begin(), unique.end(), path) == unique.end()) unique.push_back(std::move(path));
  }
  return unique;
}

const OpenVdbFunctions* load() {
  std::string tried;
  for (const std::filesystem::path& path : candidates()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      continue;
    }
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = ::dlerror();
      throw IoError("cannot load the .vdb reader " + path.string() + ": " + (why ? why : "unknown error"));
    }
    using Entry = const OpenVdbFunctions* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, "isopatch_openvdb_functions"));
    const OpenVdbFunctions* functions = entry ? entry() : nullptr;
    if (functions == nullptr || functions->version != kOpenVdbPluginVersion)
      throw IoError("the .vdb reader " + path.string() +
                    " is of another isopatch build (reinstall isopatch)");
    functions->initialize();
    return functions;  // kept loaded until exit
  }
  throw IoError("cannot read .vdb files: the OpenVDB reader (" + std::string(kPluginName) +
                ") is not installed; looked in " + tried);
}

}  // namespace

const OpenVdbFunctions& openvdb_functions() {
  static std::mutex mutex;
  static const OpenVdbFunctions* loaded = nullptr;
  const std::lock_guard lock(mutex);
  if (loaded == nullptr) loaded = load();  // a failed load is tried again next time
  return *loaded;
}

#endif

}  // namespace isopatch::vdb
