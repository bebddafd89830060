// The three template layouts. Boundary vertices are tagged where they are created (never recovered by
// index arithmetic afterwards) and placed with Domain::side_point(k, i, r).
#include "ngon/template_layouts.hpp"

#include <cassert>

namespace isopatch {
namespace {

/// Vertex i of r on side k: corner k at i = 0, corner k + 1 at i = r, a side vertex in between.
VertexTag boundary_tag(const Domain& domain, int k, int i, int r) {
  if (i == 0) return {VertexTag::Kind::Corner, domain.wrap(k), 0};
  if (i == r) return {VertexTag::Kind::Corner, domain.wrap(k + 1), 0};
  return {VertexTag::Kind::Side, domain.wrap(k), i};
}

void add_boundary(TemplateLayout& layout, const Domain& domain, int k, int i, int r) {
  layout.points.push_back(domain.side_point(k, i, r));
  layout.tags.push_back(boundary_tag(domain, k, i, r));
}

void add_interior(TemplateLayout& layout, const Vec2& p) {
  layout.points.push_back(p);
  layout.tags.push_back({});
}

}  // namespace

TemplateLayout triangle_grid_layout(const Domain& domain, int r) {
  assert(domain.sides() == 3);
  TemplateLayout layout;
  // Row c holds the lattice points with c steps towards V_2: b = 0..r-c steps towards V_1, the rest
  // (a) towards V_0. Row 0 is side 0 (V_0 -> V_1); the last point of each row lies on side 1 and the
  // first on side 2.
  for (int c = 0; c <= r; ++c) {
    for (int b = 0; b <= r - c; ++b) {
      const int a = r - c - b;
      if (c == 0) {
        add_boundary(layout, domain, 0, b, r);
      } else if (a == 0) {
        add_boundary(layout, domain, 1, c, r);
      } else if (b == 0) {
        add_boundary(layout, domain, 2, a, r);
      } else {
        const double scale = 1.0 / r;
        add_interior(layout, (scale * a) * domain.vertex(0) + (scale * b) * domain.vertex(1) +
                                 (scale * c) * domain.vertex(2));
      }
    }
  }
  // Between row c (start s, r-c+1 points) and row c+1 (start t): "up" triangles (s+b, s+b+1, t+b) and,
  // between them, "down" triangles (s+b+1, t+b+1, t+b). Both are ccw because (V_0, V_1, V_2) is.
  int s = 0;
  for (int c = 0; c < r; ++c) {
    const int t = s + (r - c + 1);
    const int segments = r - c;
    for (int b = 0; b < segments; ++b) {
      layout.triangles.push_back({s + b, s + b + 1, t + b});
      if (b + 1 < segments) layout.triangles.push_back({s + b + 1, t + b + 1, t + b});
    }
    s = t;
  }
  return layout;
}

TemplateLayout quad_grid_layout(const Domain& domain, int r) {
  assert(domain.sides() == 4);
  TemplateLayout layout;
  // Grid point (a, b) = V_2 + (a/r)(V_3 - V_2) + (b/r)(V_1 - V_2), index b (r+1) + a. On the square
  // V_2 = (-1,-1), so a runs along +x and b along +y.
  const Vec2 origin = domain.vertex(2);
  const Vec2 du = domain.vertex(3) - origin;
  const Vec2 dv = domain.vertex(1) - origin;
  for (int b = 0; b <= r; ++b) {
    for (int a = 0; a <= r; ++a) {
      if (b == r) {
        add_boundary(layout, domain, 0, r - a, r);  // V_0 = (1,1) -> V_1 = (-1,1)
      } else if (a == 0) {
        add_boundary(layout, domain, 1, r - b, r);  // V_1 -> V_2 = (-1,-1)
      } else if (b == 0) {
        add_boundary(layout, domain, 2, a, r);  // V_2 -> V_3 = (1,-1)
      } else if (a == r) {
        add_boundary(layout, domain, 3, b, r);  // V_3 -> V_0
      } else {
        add_interior(layout, origin + (static_cast<double>(a) / r) * du + (static_cast<double>(b) / r) * dv);
      }
    }
  }
  // One diagonal direction everywhere, (a, b) -> (a+1, b+1), so interior valences are all 6.
  for (int b = 0; b < r; ++b) {
    for (int a = 0; a < r; ++a) {
      const int p00 = b * (r + 1) + a;
      const int p10 = p00 + 1;
      const int p01 = p00 + r + 1;
      const int p11 = p01 + 1;
      layout.triangles.push_back({p00, p10, p11});
      layout.triangles.push_back({p00, p11, p01});
    }
  }
  return layout;
}

TemplateLayout ring_layout(const Domain& domain, int r) {
  const int n = domain.sides();
  TemplateLayout layout;
  layout.centre = 0;
  add_interior(layout, Vec2::Zero());
  // Ring j (1..r) starts at 1 + n j (j-1)/2 and holds, side by side, the points j-th of the way from
  // the centre to side k: (j/r) side_point(k, i, j) for i = 0..j-1. Ring r is the boundary.
  for (int j = 1; j <= r; ++j) {
    for (int k = 0; k < n; ++k) {
      for (int i = 0; i < j; ++i) {
        if (j == r) {
          add_boundary(layout, domain, k, i, r);
        } else {
          add_interior(layout, (static_cast<double>(j) / r) * domain.side_point(k, i, j));
        }
      }
    }
  }
  const auto ring_vertex = [n](int j, int k, int i) {
    if (j == 0) return 0;
    return 1 + n * j * (j - 1) / 2 + (k * j + i) % (n * j);
  };
  // Layer L joins ring L-1 to ring L. Along side k the outer ring has L segments and the inner one
  // L-1: L outward triangles (inner, outer, next outer), and between them L-1 inward ones
  // (inner, next outer, next inner). 2L-1 triangles per side, all ccw.
  for (int layer = 1; layer <= r; ++layer) {
    for (int k = 0; k < n; ++k) {
      for (int b = 0; b < layer; ++b) {
        const int inner = ring_vertex(layer - 1, k, b);
        layout.triangles.push_back({inner, ring_vertex(layer, k, b), ring_vertex(layer, k, b + 1)});
        if (b + 1 < layer) {
          layout.triangles.push_back({inner, ring_vertex(layer, k, b + 1), ring_vertex(layer - 1, k, b + 1)});
        }
      }
    }
  }
  return layout;
}

}  // namespace isopatch
