#include "partition/cell_checks.hpp"

#include <array>
#include <utility>

#include "core/cube_numbering.hpp"
#include "partition/cell_tests.hpp"
#include "surface/bracketed_root.hpp"

namespace isopatch {

bool face_gradients_agree(SampleCache& cache, const Cell& cell, int face) {
  std::array<Vec3, 5> g;
  for (int k = 0; k < 4; ++k) g[k] = cache.gradient(cell.corner_half(cube::kFace[face][k]));
  g[4] = cache.gradient(cell.face_centre_half(face));
  return in_plane_gradients_agree(g, cube::kFaceAxis[face]);
}

bool cell_gradients_within_cone(SampleCache& cache, const Cell& cell, const std::vector<Loop>& loops,
                                const std::vector<Crossing>& crossings, double cos_cone) {
  std::vector<Vec3> g;
  g.reserve(15 + 6);
  for (int i = 0; i < 8; ++i) g.push_back(cache.gradient(cell.corner_half(i)));
  g.push_back(cache.gradient(cell.centre_half()));
  for (int f = 0; f < 6; ++f) g.push_back(cache.gradient(cell.face_centre_half(f)));
  for (const Loop& loop : loops)
    for (std::uint32_t c : loop.corners) g.push_back(crossings[c].gradient);
  return gradients_within_cone(g, cos_cone);
}

bool loop_oriented_along_gradient(const Loop& loop, const std::vector<Crossing>& crossings) {
  std::vector<Vec3> points;
  Vec3 mean = Vec3::Zero();
  for (std::uint32_t c : loop.corners) {
    points.push_back(crossings[c].position);
    const double norm = crossings[c].gradient.norm();
    if (norm > 0.0) mean += crossings[c].gradient / norm;
  }
  return newell_normal(points).dot(mean) > 0.0;
}

Crossing segment_crossing(const Sampler& sampler, const Lattice& lattice, const SegmentKey& key, double fa,
                          double fb, double tolerance, int max_iterations, std::uint64_t& root_evaluations) {
  Vec3 a = lattice.point(key.start);
  Vec3 b = lattice.point(key.end());
  if (!is_negative(fa)) {
    std::swap(a, b);
    std::swap(fa, fb);
  }
  const Vec3 ab = b - a;
  auto phi = [&](double t) {
    ++root_evaluations;
    return sampler.value(a + t * ab);
  };
  const double t = bracketed_root(phi, 0.0, fa, 1.0, fb, tolerance, max_iterations);
  Crossing c;
  c.segment = key;
  c.position = a + t * ab;
  c.direction = ab.normalized();
  c.gradient = sampler.value_gradient(c.position).gradient;
  return c;
}

}  // namespace isopatch
