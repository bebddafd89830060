#pragma once
/// \file vertex_role.hpp
/// What made a vertex of the projection mesh, stored per vertex as the attribute "role" when
/// Settings::vertex_roles is set (its numeric values are part of that attribute's documented meaning).
/// In the lowest layer: the projection writes the roles, the clean-up keeps them up to date.

#include <cstdint>

namespace isopatch {

enum class VertexRole : std::uint8_t {
  Corner = 0,     ///< a patch corner: the crossing of f = 0 with a cell edge
  Side = 1,       ///< a boundary vertex on a patch side, shared by the two patches of that side
  Interior = 2,   ///< an interior template vertex of one patch
  Centre = 3,     ///< the centre vertex of a ring template
  FanCentre = 4,  ///< the centre of a fallback fan that closes a cell no patch could mesh
  Remeshed = 5,   ///< made or moved by the clean-up: a split's midpoint, a composite patch's relaxed interior
};

/// The value stored in the "role" attribute.
constexpr float role_value(VertexRole role) {
  return static_cast<float>(static_cast<std::uint8_t>(role));
}

}  // namespace isopatch
