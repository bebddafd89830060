#pragma once
/// \file template_layouts.hpp
/// The three connectivity layouts behind PatchTemplate (internal to src/ngon). Each produces domain
/// points, boundary tags and counter-clockwise triangles; boundary points are placed with
/// Domain::side_point() at t = i/r. Topologies as in salvipeter/c0coons, re-indexed to the convention of
/// domain.hpp.

#include "ngon/domain.hpp"
#include "ngon/patch_template.hpp"

#include <vector>

namespace isopatch {

struct TemplateLayout {
  std::vector<Vec2> points;
  std::vector<VertexTag> tags;
  std::vector<TemplateTriangle> triangles;
  int centre = -1;
};

/// n = 3: lattice points (a V_0 + b V_1 + c V_2) / r with a + b + c = r, in rows of constant c.
/// V = (r+1)(r+2)/2, T = r^2; interior valence 6.
TemplateLayout triangle_grid_layout(const Domain& domain, int r);

/// n = 4: the (r+1)^2 grid, every quad split along the diagonal parallel to V_2 -> V_0.
/// V = (r+1)^2, T = 2 r^2; interior valence 6.
TemplateLayout quad_grid_layout(const Domain& domain, int r);

/// n >= 5 (works for any n): the centre and r rings; ring j is the boundary scaled by j/r with j
/// segments per side. V = 1 + n r(r+1)/2, T = n r^2; interior valence 6, centre valence n.
TemplateLayout ring_layout(const Domain& domain, int r);

}  // namespace isopatch
