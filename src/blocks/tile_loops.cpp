// The loops of a tile's cut from its faces' curves (tile_seam.hpp).
#include <isopatch/error.hpp>

#include "blocks/tile_seam.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <map>

namespace isopatch::blocks {
namespace {

using PointKey = std::array<std::uint64_t, 3>;

PointKey key(const Vec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x()), std::bit_cast<std::uint64_t>(p.y()),
          std::bit_cast<std::uint64_t>(p.z())};
}

[[noreturn]] void unjoinable(const Vec3& p) {
  throw LimitError("a curve of f = 0 passes through a corner of a tile near (" + std::to_string(p.x()) +
                       ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) +
                       "): use another number of tiles",
                   "tiles");
}

}  // namespace

std::vector<std::vector<Vec3>> tile_loops(std::span<const FaceCurves> faces) {
  std::vector<std::vector<Vec3>> open, loops;
  for (const FaceCurves& face : faces)
    for (const auto& curve : face.curves) {
      std::vector<Vec3> points;
      points.reserve(curve.size());
      for (const std::uint32_t p : curve) points.push_back(face.points[p]);
      if (curve.size() > 1 && curve.front() == curve.back()) {
        points.pop_back();
        loops.push_back(std::move(points));
      } else {
        open.push_back(std::move(points));
      }
    }
  // Per end: the curves that end there (curve number, 0 at its start, 1 at its end).
  std::map<PointKey, std::vector<std::array<std::size_t, 2>>> ends;
  for (std::size_t c = 0; c < open.size(); ++c) {
    ends[key(open[c].front())].push_back({c, 0});
    ends[key(open[c].back())].push_back({c, 1});
  }
  for (const auto& [point, list] : ends)
    if (list.size() != 2)
      unjoinable(Vec3(std::bit_cast<double>(point[0]), std::bit_cast<double>(point[1]),
                      std::bit_cast<double>(point[2])));
  std::vector<std::uint8_t> used(open.size(), 0);
  for (std::size_t first = 0; first < open.size(); ++first) {
    if (used[first]) continue;
    std::vector<Vec3> loop;
    std::size_t c = first;
    bool forward = true;
    for (;;) {
      used[c] = 1;
      const auto& points = open[c];
      // Every point of the curve but its last (the next curve starts there).
      if (forward)
        loop.insert(loop.end(), points.begin(), points.end() - 1);
      else
        loop.insert(loop.end(), points.rbegin(), points.rend() - 1);
      const Vec3& last = forward ? points.back() : points.front();
      const auto& list = ends.at(key(last));
      const std::array<std::size_t, 2> self{c, forward ? std::size_t{1} : std::size_t{0}};
      const auto& other = list[0] == self ? list[1] : list[0];
      if (other[0] == first && used[first] && loop.size() > 1 && key(last) == key(loop.front())) break;
      if (used[other[0]]) unjoinable(last);
      c = other[0];
      forward = other[1] == 0;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace isopatch::blocks
