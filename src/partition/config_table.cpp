// Generation of the configuration table (docs/algorithms.md 2.5): classify each of the 256 sign patterns by
// its ambiguous faces and by the number of cycles the face-by-face linking gives.
#include "partition/config_table.hpp"

#include "partition/cube_cycles.hpp"

#include <algorithm>

namespace isopatch {

namespace {

ConfigEntry classify(std::uint8_t negative) {
  ConfigEntry entry;
  entry.crossed_edges = crossed_edges(negative);
  if (entry.crossed_edges == 0) return entry;
  for (int f = 0; f < 6; ++f) {
    if (face_ambiguous(negative, f)) {
      entry.kind = ConfigClass::Ambiguous;
      return entry;
    }
  }
  // No face is ambiguous, so the face centres are never consulted.
  const auto cycles = cube_cycles(negative, 0);
  entry.loops = static_cast<std::uint8_t>(cycles.size());
  for (const auto& cycle : cycles)
    entry.loop_size = std::max(entry.loop_size, static_cast<std::uint8_t>(cycle.edges.size()));
  entry.kind = cycles.size() == 1 ? ConfigClass::SingleLoop : ConfigClass::SeveralLoops;
  return entry;
}

}  // namespace

const std::array<ConfigEntry, 256>& config_table() {
  static const std::array<ConfigEntry, 256> table = [] {
    std::array<ConfigEntry, 256> t{};
    for (int code = 0; code < 256; ++code) t[code] = classify(static_cast<std::uint8_t>(code));
    return t;
  }();
  return table;
}

}  // namespace isopatch
