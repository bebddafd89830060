// Self-intersection test of a triangle mesh (see include/isopatch/self_intersection.hpp): a bounding
// volume hierarchy over the triangles' boxes, traversed against itself so that every pair of
// overlapping boxes is met once (triangle_tree.hpp); each such pair is decided by segment-against-
// triangle tests (two triangles in general position meet iff an edge of one meets the other, since
// each end of the segment where they meet lies on an edge of one of them). Pairs around a vertex whose
// fan is proved to meet itself only where it shares (flat_fans.hpp: 99% of the pairs) are skipped.
#include <isopatch/error.hpp>
#include <isopatch/self_intersection.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "analysis/exact_predicates.hpp"
#include "analysis/flat_fans.hpp"
#include "analysis/mesh_neighbourhood.hpp"
#include "analysis/triangle_tree.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace isopatch {
namespace {

/// Six times the signed volume of (a, b, c, d), rounded: for the position of a crossing only; every
/// decision uses the exact signs of exact_predicates.hpp.
double signed_volume6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a);
}

/// A point of the plane that drops one coordinate axis (the one where a triangle's normal is largest).
struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

Point2 drop_axis(const Vec3& v, int dropped) {
  const int i = (dropped + 1) % 3, j = (dropped + 2) % 3;
  return {v[i], v[j]};
}

int dominant_axis(const Vec3& n) {
  const Vec3 a = n.cwiseAbs();
  return a.x() >= a.y() ? (a.x() >= a.z() ? 0 : 2) : (a.y() >= a.z() ? 1 : 2);
}

int orient2d(Point2 a, Point2 b, Point2 c) {
  return exact::orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Signs that are not strictly one positive and one negative.
bool opposite_or_zero(int s, int t) {
  return s * t <= 0;
}

/// Signs of which none is positive, or none negative.
bool one_side(int s1, int s2, int s3) {
  const bool negative = s1 < 0 || s2 < 0 || s3 < 0;
  const bool positive = s1 > 0 || s2 > 0 || s3 > 0;
  return !(negative && positive);
}

/// Closed segments pq and ab meet (touching and collinear overlap included).
bool segments_meet_2d(Point2 p, Point2 q, Point2 a, Point2 b) {
  const int d1 = orient2d(a, b, p), d2 = orient2d(a, b, q);
  if (d1 == 0 && d2 == 0) {  // collinear: overlap of the projections on the longer axis
    const bool use_x = std::abs(q.x - p.x) + std::abs(b.x - a.x) >= std::abs(q.y - p.y) + std::abs(b.y - a.y);
    const auto key = [use_x](Point2 v) { return use_x ? v.x : v.y; };
    return std::max(std::min(key(p), key(q)), std::min(key(a), key(b))) <=
           std::min(std::max(key(p), key(q)), std::max(key(a), key(b)));
  }
  return opposite_or_zero(d1, d2) && opposite_or_zero(orient2d(p, q, a), orient2d(p, q, b));
}

/// Closed triangle abc contains p.
bool contains_2d(Point2 a, Point2 b, Point2 c, Point2 p) {
  return one_side(orient2d(a, b, p), orient2d(b, c, p), orient2d(c, a, p));
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

/// Triangles s and t of `mesh` meet other than in what they share by index (see the header).
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

/// Whether s and t share a vertex whose fan is proved to meet itself only in shared vertices and edges
/// (flat_fans.hpp): then the pair does not meet otherwise.
bool share_a_flat_fan(const Triangle& s, const Triangle& t, const std::vector<std::uint8_t>& flat) {
  for (const std::uint32_t v : s)
    if (flat[v] != 0 && (v == t[0] || v == t[1] || v == t[2])) return true;
  return false;
}

/// Triangles per piece of the parallel pair scan: a few dozen pieces on a 20k-vertex mesh.
constexpr std::size_t kTrianglesPerJob = 1024;

}  // namespace

SelfIntersectionReport find_self_intersections(const Mesh& mesh, std::size_t limit) {
  analysis::check_mesh(mesh, "find_self_intersections");
  if (mesh.triangles.size() >= std::numeric_limits<std::uint32_t>::max())
    throw InputError("find_self_intersections: more than 2^32 triangles");
  SelfIntersectionReport report;
  if (limit == 0) return report;
  // The fans first: their incidence lists are freed before the tree is made.
  const std::vector<std::uint8_t> flat = analysis::flat_fans(mesh);
  const analysis::TriangleTree tree(mesh, analysis::z_ordered_triangles(mesh));
  // The scan in pieces, in parallel; each piece counts its own pairs (up to the limit) and keeps its
  // first. In the pieces' order, the first piece with a pair has the scan's first pair: the same report
  // as one scan, for any number of threads.
  struct Found {
    std::size_t pairs = 0;
    std::array<std::size_t, 2> example{};
    Vec3 at = Vec3::Zero();
  };
  const std::vector<analysis::TriangleTree::Job> jobs = tree.jobs(kTrianglesPerJob);
  std::vector<Found> found(jobs.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, jobs.size(), 1), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      Found& f = found[k];
      tree.run(jobs[k], [&](std::size_t a, std::size_t b) {
        const std::size_t i = tree.triangle(a), j = tree.triangle(b);
        if (share_a_flat_fan(mesh.triangles[i], mesh.triangles[j], flat)) return true;
        Vec3 at;
        if (!triangles_meet(mesh, mesh.triangles[i], mesh.triangles[j], &at)) return true;
        if (f.pairs++ == 0) {
          f.example = {std::min(i, j), std::max(i, j)};
          f.at = at;
        }
        return f.pairs < limit;
      });
    }
  });
  std::size_t total = 0;
  for (const Found& f : found) {
    if (total == 0 && f.pairs > 0) {
      report.example = f.example;
      report.example_point = f.at;
    }
    total += f.pairs;
  }
  report.pairs = std::min(total, limit);
  report.capped = total >= limit;
  return report;
}

}  // namespace isopatch
