// triangles_meet (triangle_pair.hpp).
#include "analysis/triangle_pair.hpp"

#include <array>
#include <cstddef>

#include "analysis/exact_predicates.hpp"
#include "analysis/segments_2d.hpp"

namespace isopatch::analysis {
namespace {

/// Six times the signed volume of (a, b, c, d), rounded: for the position of a crossing only; every
/// decision uses the exact signs of exact_predicates.hpp.
double signed_volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a);
}

int dominant_axis(const Vec3& n) {
  const Vec3 a = n.cwiseAbs();
  return a.x() >= a.y() ? (a.x() >= a.z() ? 0 : 2) : (a.y() >= a.z() ? 1 : 2);
}

/// The closed segment pq meets the closed triangle abc; *at receives a point they share.
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                            Vec3* at) {
  const int sp = exact::orient3d(a, b, c, p), sq = exact::orient3d(a, b, c, q);
  if (sp * sq > 0) return false;
  if (sp == 0 && sq == 0) {  // in the triangle's plane: decide in 2D
    const Vec3 normal = (b - a).cross(c - a);
    if (normal.squaredNorm() == 0.0) return false;  // a degenerate triangle has no plane
    const int axis = dominant_axis(normal);
    const Point2 p2 = drop_axis(p, axis), q2 = drop_axis(q, axis);
    const Point2 a2 = drop_axis(a, axis), b2 = drop_axis(b, axis), c2 = drop_axis(c, axis);
    if (contains_2d(a2, b2, c2, p2)) {
      *at = p;
      return true;
    }
    if (contains_2d(a2, b2, c2, q2)) {
      *at = q;
      return true;
    }
    const Vec3* corners[3] = {&a, &b, &c};
    const Point2 corners2[3] = {a2, b2, c2};
    for (int e = 0; e < 3; ++e)
      if (segments_meet_2d(p2, q2, corners2[e], corners2[(e + 1) % 3])) {
        *at = 0.5 * (*corners[e] + *corners[(e + 1) % 3]);
        return true;
      }
    return false;
  }
  // The segment reaches the plane; the point where it does lies in the triangle iff the line pq passes
  // every edge on the same side.
  if (!one_side(exact::orient3d(p, q, a, b), exact::orient3d(p, q, b, c), exact::orient3d(p, q, c, a)))
    return false;
  const double dp = signed_volume6(a, b, c, p), dq = signed_volume6(a, b, c, q);
  *at = dp == dq ? p : Vec3(p + dp / (dp - dq) * (q - p));
  return true;
}

}  // namespace

bool triangles_meet(const Mesh& mesh, const Triangle& s, const Triangle& t, Vec3* at) {
  int shared = 0;
  int s_only[3], t_only[3];  // positions in s (t) of the vertices t (s) does not have
  int ns = 0, nt = 0;
  for (int i = 0; i < 3; ++i) {
    const bool in_t = s[i] == t[0] || s[i] == t[1] || s[i] == t[2];
    shared += in_t ? 1 : 0;
    if (!in_t) s_only[ns++] = i;
    const bool in_s = t[i] == s[0] || t[i] == s[1] || t[i] == s[2];
    if (!in_s) t_only[nt++] = i;
  }
  const auto& x = mesh.positions;
  const auto vertex = [&](const Triangle& tri, int i) -> const Vec3& {
    return x[tri[static_cast<std::size_t>(i)]];
  };
  // Whether the corners `which` of tri (-1: none) lie strictly on one side of the plane through a, b, c.
  const auto strictly_one_side = [&](const Vec3& a, const Vec3& b, const Vec3& c, std::array<int, 3> which,
                                     const Triangle& tri) {
    int side = 0;
    for (const int k : which) {
      if (k < 0) continue;
      const int sign = exact::orient3d(a, b, c, vertex(tri, k));
      if (sign == 0 || (side != 0 && sign != side)) return false;
      side = sign;
    }
    return true;
  };
  const auto edge_meets = [&](const Triangle& a, int i, int j, const Triangle& b) {
    return segment_meets_triangle(vertex(a, i), vertex(a, j), vertex(b, 0), vertex(b, 1), vertex(b, 2), at);
  };
  switch (shared) {
    case 0:
      // A triangle strictly on one side of the other's plane does not meet it.
      if (strictly_one_side(vertex(t, 0), vertex(t, 1), vertex(t, 2), {0, 1, 2}, s) ||
          strictly_one_side(vertex(s, 0), vertex(s, 1), vertex(s, 2), {0, 1, 2}, t))
        return false;
      for (int i = 0; i < 3; ++i)
        if (edge_meets(s, i, (i + 1) % 3, t) || edge_meets(t, i, (i + 1) % 3, s)) return true;
      return false;
    case 1:
      // Meeting anywhere but the common vertex means meeting the edge opposite it in the other; when
      // that edge of one lies strictly on one side of the other's plane, the two meet in that plane only
      // at the common vertex.
      if (strictly_one_side(vertex(t, 0), vertex(t, 1), vertex(t, 2), {s_only[0], s_only[1], -1}, s) ||
          strictly_one_side(vertex(s, 0), vertex(s, 1), vertex(s, 2), {t_only[0], t_only[1], -1}, t))
        return false;
      return edge_meets(s, s_only[0], s_only[1], t) || edge_meets(t, t_only[0], t_only[1], s);
    case 2: {
      // Folded flat: the third vertices in the plane of the common edge, on the same side of it.
      const Vec3& u = vertex(s, (s_only[0] + 1) % 3);
      const Vec3& w = vertex(s, (s_only[0] + 2) % 3);
      const Vec3& a = vertex(s, s_only[0]);
      const Vec3& b = vertex(t, t_only[0]);
      if (exact::orient3d(u, w, a, b) != 0) return false;
      const Vec3 normal = (w - u).cross(a - u);
      if (normal.squaredNorm() == 0.0) return false;
      const int axis = dominant_axis(normal);
      const int side_a = orient2d(drop_axis(u, axis), drop_axis(w, axis), drop_axis(a, axis));
      const int side_b = orient2d(drop_axis(u, axis), drop_axis(w, axis), drop_axis(b, axis));
      if (side_a * side_b <= 0) return false;
      *at = u;
      return true;
    }
    default:
      *at = vertex(s, 0);
      return true;  // the same triangle twice
  }
}

}  // namespace isopatch::analysis
