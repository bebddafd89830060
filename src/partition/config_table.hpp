#pragma once
/// \file config_table.hpp
/// The corner-sign configuration table of docs/algorithms.md 2.5, generated at start-up by linking
/// crossed edges face by face (cube_cycles.hpp), never pasted from elsewhere.

#include <array>
#include <cstdint>

namespace isopatch {

enum class ConfigClass : std::uint8_t {
  Empty,         ///< all corners have one sign: no crossed edge
  SingleLoop,    ///< no ambiguous face and the crossed edges form one cycle (a disk candidate)
  SeveralLoops,  ///< no ambiguous face but more than one cycle (two triangles at opposite corners)
  Ambiguous,     ///< at least one face has 4 crossed edges
};

struct ConfigEntry {
  ConfigClass kind = ConfigClass::Empty;
  std::uint8_t loops = 0;           ///< number of cycles (0 for Empty and Ambiguous)
  std::uint8_t loop_size = 0;       ///< corners of the loop for SingleLoop, of the largest loop otherwise
  std::uint16_t crossed_edges = 0;  ///< bit e set when edge e of the cube is crossed
};

/// The 256-entry table, indexed by the configuration code: bit i set when corner i
/// (core/cube_numbering.hpp) is negative. Built once on first use (thread-safe); docs/algorithms.md 2.5
/// lists the expected counts: 2 empty, 126 single loops (16 triangles, 30 quads, 48 pentagons, 32
/// hexagons), 8 double triangles, 120 ambiguous.
const std::array<ConfigEntry, 256>& config_table();

}  // namespace isopatch
