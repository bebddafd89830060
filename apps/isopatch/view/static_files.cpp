// resolve_static and friends (static_files.hpp): lexical checks first, then the real paths.
#include "view/static_files.hpp"

#include <algorithm>

namespace isopatch::view {

bool is_safe_url_path(std::string_view path) {
  if (path.empty() || path.front() != '/' || path.size() > 1024) return false;
  for (const char c : path)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f || c == '\\') return false;
  std::size_t start = 1;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string_view segment = path.substr(start, end - start);
    const bool last = end == path.size();
    if ((segment.empty() && !last) || segment == "." || segment == "..") return false;
    start = end + 1;
  }
  return true;
}

std::optional<std::filesystem::path> resolve_static(const std::vector<Mount>& mounts, std::string_view path) {
  namespace fs = std::filesystem;
  if (!is_safe_url_path(path)) return std::nullopt;
  const Mount* best = nullptr;
  for (const Mount& m : mounts)
    if (path.substr(0, m.prefix.size()) == m.prefix &&
        (best == nullptr || m.prefix.size() > best->prefix.size()))
      best = &m;
  if (best == nullptr) return std::nullopt;
  std::string rest(path.substr(best->prefix.size()));
  if (rest.empty() || rest.back() == '/') rest += "index.html";
  std::error_code ec;
  const fs::path root = fs::canonical(best->folder, ec);
  if (ec) return std::nullopt;
  const fs::path file = fs::canonical(root / rest, ec);
  if (ec || !fs::is_regular_file(file, ec)) return std::nullopt;
  // Inside the root: the root's components are a prefix of the file's.
  const auto [root_end, file_at] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  if (root_end != root.end()) return std::nullopt;
  return file;
}

std::string content_type_for(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  return "application/octet-stream";
}

}  // namespace isopatch::view
