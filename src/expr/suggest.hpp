#pragma once
// "did you mean ...?" for a misspelt name, shared by the parser and the surface resolver.

#include "core/edit_distance.hpp"

#include <cctype>
#include <string>
#include <string_view>

namespace isopatch::expr {

/// The candidate closest to `name` by edit distance, when it is close enough to be a plausible typo,
/// else "". Plausible: the same name in another case, one edit (in a name of two or more
/// characters), two edits in a name of four or more, or at most a third of the name.
template <class Range>
std::string closest_name(std::string_view name, const Range& candidates) {
  const auto lower = [](std::string_view s) {
    std::string l(s);
    for (char& c : l) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return l;
  };
  std::string best;
  std::size_t best_distance = 0;
  for (const auto& c : candidates) {
    const std::string_view candidate(c);
    if (lower(candidate) == lower(name)) return std::string(candidate);
    const std::size_t d = edit_distance(name, candidate);
    if (best.empty() || d < best_distance) {
      best = std::string(candidate);
      best_distance = d;
    }
  }
  const std::size_t n = name.size();
  const bool close =
      (best_distance == 1 && n >= 2) || (best_distance == 2 && n >= 4) || 3 * best_distance <= n;
  return (!best.empty() && close) ? best : std::string();
}

/// " (did you mean 'torus'?)" or "".
inline std::string did_you_mean(const std::string& suggestion) {
  return suggestion.empty() ? std::string() : " (did you mean '" + suggestion + "'?)";
}

}  // namespace isopatch::expr
