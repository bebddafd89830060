#pragma once
// Where a new vertex starts before it is put on f = 0: Phong tessellation (Boubekeur & Alexa 2008,
// "Phong Tessellation", SIGGRAPH Asia): the flat point of the base triangle pulled towards the tangent
// planes of its corners. Made from the corners' positions and unit normals alone, so a point on a base
// edge depends on that edge's two ends only. The start is a second-order guess of the surface, so the
// projection onto f = 0 is short and moves the lattice little.

#include <isopatch/geometry.hpp>

namespace isopatch::refine {

/// Share of the Phong displacement taken (Boubekeur & Alexa recommend 3/4: a full step overshoots on
/// strongly curved triangles).
inline constexpr double kPhongShape = 0.75;

/// The start of the point with barycentric weights w of corners p[0..2] with unit normals n[0..2].
/// \pre w sums to 1.
inline Vec3 phong_point(const Vec3 (&p)[3], const Vec3 (&n)[3], const double (&w)[3]) {
  const Vec3 flat = w[0] * p[0] + w[1] * p[1] + w[2] * p[2];
  Vec3 pulled = Vec3::Zero();
  for (int c = 0; c < 3; ++c) pulled += w[c] * (flat - (flat - p[c]).dot(n[c]) * n[c]);
  return (1.0 - kPhongShape) * flat + kPhongShape * pulled;
}

/// The start of the point at parameter s in [0, 1] from a (normal na) to b (normal nb): phong_point
/// restricted to an edge.
inline Vec3 phong_edge_point(const Vec3& a, const Vec3& na, const Vec3& b, const Vec3& nb, double s) {
  const Vec3 flat = (1.0 - s) * a + s * b;
  const Vec3 pulled = (1.0 - s) * (flat - (flat - a).dot(na) * na) + s * (flat - (flat - b).dot(nb) * nb);
  return (1.0 - kPhongShape) * flat + kPhongShape * pulled;
}

}  // namespace isopatch::refine
