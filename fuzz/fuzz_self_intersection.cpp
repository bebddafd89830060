// libFuzzer target: the self-intersection check (find_self_intersections) against the exact test of
// every pair of triangles (triangles_meet, src/analysis/triangle_pair.hpp), on meshes made from the
// input: a grid of up to 12 x 12 vertices whose positions the bytes move (folds, overlaps seen from
// every axis, coplanar pieces), optionally a second grid through or over it, triangles turned over,
// vertices merged (pinches, repeated indices) and the order shuffled. The check skips pairs it proves
// apart (flat fans, flat discs: src/analysis/flat_discs.hpp); its count must equal the pairwise one.
#include <isopatch/self_intersection.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "analysis/triangle_pair.hpp"

namespace {

/// The bytes, read one at a time; zeros past the end.
struct Bytes {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  int next() { return at < size ? data[at++] : 0; }
  /// A signed byte over `scale`.
  double offset(double scale) { return static_cast<std::int8_t>(next()) / 128.0 * scale; }
};

/// A grid of n x n vertices, spacing 1, moved by the bytes: in x and y by under half a spacing (or up to
/// two spacings when `wild`), in z by up to 2, in plane z = height.
void add_grid(isopatch::Mesh& m, Bytes& b, int n, double height, bool wild) {
  const auto first = static_cast<std::uint32_t>(m.positions.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double reach = wild ? 2.0 : 0.45;
      m.positions.emplace_back(i + b.offset(reach), j + b.offset(reach), height + b.offset(2.0));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto v = first + static_cast<std::uint32_t>(j * n + i), w = static_cast<std::uint32_t>(n);
      m.triangles.push_back({v, v + 1, v + w + 1});
      m.triangles.push_back({v, v + w + 1, v + w});
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes b{data, size};
  const int n = 3 + b.next() % 10;
  const int flags = b.next();
  isopatch::Mesh m;
  add_grid(m, b, n, 0.0, (flags & 1) != 0);
  if ((flags & 2) != 0) add_grid(m, b, 3 + b.next() % 6, b.offset(2.0), (flags & 4) != 0);
  if ((flags & 8) != 0)  // some triangles turned over
    for (int k = b.next() % 8; k > 0; --k) {
      isopatch::Triangle& t = m.triangles[static_cast<std::size_t>(b.next()) % m.triangles.size()];
      std::swap(t[1], t[2]);
    }
  if ((flags & 16) != 0)  // vertices merged into others: pinches, shared edges, repeated indices
    for (int k = b.next() % 4; k > 0; --k) {
      const auto from = static_cast<std::uint32_t>(static_cast<std::size_t>(b.next()) % m.positions.size());
      const auto into = static_cast<std::uint32_t>(static_cast<std::size_t>(b.next()) % m.positions.size());
      for (isopatch::Triangle& t : m.triangles)
        for (std::uint32_t& v : t)
          if (v == from) v = into;
    }
  if ((flags & 32) != 0)  // the order shuffled by the bytes
    for (std::size_t k = m.triangles.size(); k > 1; --k)
      std::swap(m.triangles[k - 1], m.triangles[static_cast<std::size_t>(b.next()) % k]);

  const auto repeats = [](const isopatch::Triangle& t) {
    return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
  };
  // Every pair whose boxes meet (exact comparisons) decided exactly.
  std::vector<isopatch::Vec3> lo, hi;
  for (const isopatch::Triangle& t : m.triangles) {
    const isopatch::Vec3 &p = m.positions[t[0]], &q = m.positions[t[1]], &r = m.positions[t[2]];
    lo.push_back(p.cwiseMin(q).cwiseMin(r));
    hi.push_back(p.cwiseMax(q).cwiseMax(r));
  }
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    for (std::size_t j = i + 1; j < m.triangles.size(); ++j) {
      isopatch::Vec3 at;
      if ((lo[i].array() <= hi[j].array()).all() && (lo[j].array() <= hi[i].array()).all() &&
          !repeats(m.triangles[i]) && !repeats(m.triangles[j]) &&
          isopatch::analysis::triangles_meet(m, m.triangles[i], m.triangles[j], &at))
        ++pairs;
    }
  const isopatch::SelfIntersectionReport report = isopatch::find_self_intersections(m, 1000000);
  if (report.pairs != pairs) std::abort();
  return 0;
}
