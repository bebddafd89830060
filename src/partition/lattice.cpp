// Lattice geometry and keys. Positions are always computed as origin + h * (unit / 2) per coordinate
// with h an integer, so the same integer coordinates give the same bits whichever cell asks.
#include "partition/lattice.hpp"

#include "partition/index_map.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace isopatch {

namespace {

constexpr std::uint64_t kHalfRadix = (std::uint64_t{1} << 21) + 1;

std::uint64_t pack(const LatticePoint& p) {
  return half_key(p);
}

}  // namespace

double Lattice::unit() const {
  return std::ldexp(size, -max_depth);
}

Vec3 Lattice::half_point(const LatticePoint& h) const {
  const double half_unit = std::ldexp(size, -(max_depth + 1));
  return Vec3(std::clamp(origin.x() + static_cast<double>(h[0]) * half_unit, clip.lo.x(), clip.hi.x()),
              std::clamp(origin.y() + static_cast<double>(h[1]) * half_unit, clip.lo.y(), clip.hi.y()),
              std::clamp(origin.z() + static_cast<double>(h[2]) * half_unit, clip.lo.z(), clip.hi.z()));
}

Vec3 Lattice::point(const LatticePoint& p) const {
  return half_point({2 * p[0], 2 * p[1], 2 * p[2]});
}

Box Lattice::cell_box(int depth, const LatticePoint& cell) const {
  const std::uint32_t s = step(depth);
  const LatticePoint lo{cell[0] * s, cell[1] * s, cell[2] * s};
  return Box{point(lo), point({lo[0] + s, lo[1] + s, lo[2] + s})};
}

bool Lattice::inside(int depth, const LatticePoint& cell) const {
  const Box b = cell_box(depth, cell);
  return (b.lo.array() < b.hi.array()).all();
}

Lattice make_lattice(const Box& box, int max_depth) {
  if (!box.valid()) throw InputError("partition: the box must be finite with lo < hi on every axis");
  if (max_depth < 0 || max_depth > Lattice::kMaxDepth)
    throw InputError("partition: max_depth must be in 0.." + std::to_string(Lattice::kMaxDepth) + ", got " +
                     std::to_string(max_depth));
  Lattice lattice;
  lattice.max_depth = max_depth;
  lattice.size = 1.02 * box.size().maxCoeff();
  const Vec3 offset = 1e-3 * lattice.size * Vec3(0.1234, 0.5678, 0.9012);
  lattice.origin = box.centre() - Vec3::Constant(0.5 * lattice.size) + offset;
  lattice.clip = box;
  return lattice;
}

std::uint64_t half_key(const LatticePoint& h) {
  return (static_cast<std::uint64_t>(h[2]) * kHalfRadix + h[1]) * kHalfRadix + h[0];
}

LatticePoint SegmentKey::end() const {
  LatticePoint e = start;
  e[axis] += length;
  return e;
}

CellsAroundSegment cells_around_segment(const SegmentKey& key) {
  const std::uint32_t u = (key.axis + 1) % 3;
  const std::uint32_t v = (key.axis + 2) % 3;
  CellsAroundSegment around;
  for (std::uint32_t k = 0; k < 4; ++k) {
    LatticePoint p = key.start;
    if (k & 1u) {
      if (p[u] == 0) continue;
      --p[u];
    }
    if (k & 2u) {
      if (p[v] == 0) continue;
      --p[v];
    }
    around.points[around.count++] = p;
  }
  return around;
}

std::size_t SegmentKeyHash::operator()(const SegmentKey& key) const {
  return static_cast<std::size_t>(mix64(mix64(pack(key.start) * 3 + key.axis) ^ key.length));
}

std::size_t FaceIdHash::operator()(const FaceId& id) const {
  return static_cast<std::size_t>(mix64(mix64(pack(id.lower) * 3 + id.axis) ^ id.size));
}

}  // namespace isopatch
