#pragma once
// Which file a GET of the viewer's server may send: URL paths under a few mounts, each a folder,
// never anything outside them.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch::view {

/// URL prefix (starting and ending with '/') -> folder.
struct Mount {
  std::string prefix;
  std::filesystem::path folder;
};

/// True when the decoded URL path is one the server may look up at all: it starts with '/', is at
/// most 1024 characters, and has no NUL, no backslash, no control character, no empty, "." or ".."
/// segment (so no climbing out, however encoded: the path is checked after percent-decoding).
bool is_safe_url_path(std::string_view path);

/// The regular file `path` names under the longest matching mount ("/" + nothing: index.html), or
/// nothing when the path is not safe, no mount matches, the file does not exist, or the file's real
/// location (symbolic links resolved) is outside the mount's real folder.
std::optional<std::filesystem::path> resolve_static(const std::vector<Mount>& mounts, std::string_view path);

/// The Content-Type for a file name by extension (text/html, text/javascript, ...; else
/// application/octet-stream).
std::string content_type_for(const std::filesystem::path& file);

}  // namespace isopatch::view
