// The lattice of planes that cuts a domain into tiles (tiles.hpp).
#include <isopatch/error.hpp>
#include <isopatch/tiles.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace isopatch {
namespace {

constexpr int kMaxTiles = 4096;

}  // namespace

double TileGrid::plane(int axis, int index) const {
  const auto& list = planes[static_cast<std::size_t>(axis)];
  return list[static_cast<std::size_t>(std::clamp(index, 0, static_cast<int>(list.size()) - 1))];
}

double TileGrid::sample(int axis, int cell, int i, int m) const {
  const double lo = plane(axis, cell), hi = plane(axis, cell + 1);
  if (i <= 0) return lo;
  if (i >= m) return hi;
  return lo + (hi - lo) * (static_cast<double>(i) / m);
}

std::array<int, 3> TileGrid::tile(int t) const {
  return {t % counts[0], (t / counts[0]) % counts[1], t / (counts[0] * counts[1])};
}

int TileGrid::tile_number(const std::array<int, 3>& cell) const {
  return cell[0] + counts[0] * (cell[1] + counts[1] * cell[2]);
}

Box TileGrid::tile_box(const std::array<int, 3>& cell) const {
  Box box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = plane(a, cell[static_cast<std::size_t>(a)]);
    box.hi[a] = plane(a, cell[static_cast<std::size_t>(a)] + 1);
  }
  return box;
}

TileGrid make_tile_grid(const Box& domain, const std::array<int, 3>& counts) {
  if (!domain.valid()) throw SettingError("tiles", "the domain to cut into tiles is not a valid box");
  long total = 1;
  for (const int c : counts) {
    if (c < 1) throw SettingError("tiles", "every tile count must be at least 1");
    total *= c;
    if (total > kMaxTiles)
      throw SettingError("tiles", "at most " + std::to_string(kMaxTiles) + " tiles by planes");
  }
  TileGrid grid;
  grid.domain = domain;
  grid.counts = counts;
  for (int a = 0; a < 3; ++a) {
    const int n = counts[static_cast<std::size_t>(a)];
    auto& list = grid.planes[static_cast<std::size_t>(a)];
    const double lo = domain.lo[a], hi = domain.hi[a];
    for (int i = 0; i <= n; ++i)
      list.push_back(i == 0 ? lo : i == n ? hi : lo + (hi - lo) * (static_cast<double>(i) / n));
  }
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < counts[static_cast<std::size_t>(a)]; ++i)
      if (!(grid.plane(a, i) < grid.plane(a, i + 1)))
        throw SettingError("tiles", "the domain is too thin for " +
                                        std::to_string(counts[static_cast<std::size_t>(a)]) +
                                        " tiles along an axis");
  return grid;
}

namespace {

double checked(double value) {
  if (!std::isfinite(value)) throw EvaluationError("f is not finite on a plane of the tiles");
  return value;
}

/// The shortest distance between two crossings of f = 0 along the lattice line through `p` along
/// `axis` (sampled every `step`, at most 2^16 samples), or infinity with fewer than two.
double crossing_gap(const Surface& surface, Vec3 p, int axis, double lo, double hi, double step) {
  const int samples = static_cast<int>(std::min(std::ceil((hi - lo) / step), 65536.0));
  const double used = (hi - lo) / samples;
  double gap = std::numeric_limits<double>::infinity();
  int last = -1;
  bool previous = false;
  for (int i = 0; i <= samples; ++i) {
    p[axis] = i == samples ? hi : lo + (hi - lo) * (static_cast<double>(i) / samples);
    const bool in = checked(surface.value(p)) < 0.0;
    if (i > 0 && in != previous) {
      if (last >= 0) gap = std::min(gap, (i - last) * used);
      last = i;
    }
    previous = in;
  }
  return gap;
}

/// How far f = 0 keeps from the lattice on plane `index` of `axis`: the estimated distance (|f| /
/// |grad f|) of the nearest corner, or the shortest gap between two crossings of a lattice line in the
/// plane (where the surface nearly touches that line), whichever is less.
double plane_clearance(const Surface& surface, const TileGrid& grid, int axis, int index, double step) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  double nearest = std::numeric_limits<double>::infinity();
  Vec3 p;
  p[axis] = grid.plane(axis, index);
  for (int j = 0; j <= grid.counts[static_cast<std::size_t>(u)]; ++j)
    for (int k = 0; k <= grid.counts[static_cast<std::size_t>(v)]; ++k) {
      p[u] = grid.plane(u, j);
      p[v] = grid.plane(v, k);
      const ValueGradient vg = surface.value_gradient(p);
      const double g = checked(vg.gradient.norm());
      checked(vg.value);
      nearest = std::min(nearest, g > 0.0                    ? std::abs(vg.value) / g
                                  : std::abs(vg.value) > 0.0 ? nearest
                                                             : 0.0);
    }
  for (const auto& [along, across] : {std::pair{u, v}, std::pair{v, u}})
    for (int k = 0; k <= grid.counts[static_cast<std::size_t>(across)]; ++k) {
      p[across] = grid.plane(across, k);
      nearest = std::min(nearest,
                         crossing_gap(surface, p, along, grid.domain.lo[along], grid.domain.hi[along], step));
    }
  return nearest;
}

}  // namespace

TileGrid clear_tile_grid(const Surface& surface, const Box& domain, const std::array<int, 3>& counts,
                         double clearance) {
  TileGrid grid = make_tile_grid(domain, counts);
  const TileGrid even = grid;
  constexpr int kSteps = 8;  // of a fortieth of a tile each way
  for (int round = 0; round < 3; ++round) {
    bool moved = false;
    for (int a = 0; a < 3; ++a)
      for (int i = 1; i < grid.counts[static_cast<std::size_t>(a)]; ++i) {
        auto& at = grid.planes[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
        if (plane_clearance(surface, grid, a, i, 0.5 * clearance) >= clearance) continue;
        const double before = at;
        const double step = (even.plane(a, i + 1) - even.plane(a, i - 1)) / 80.0;
        double best = at, best_distance = -1.0;
        for (int s = 0; s <= 2 * kSteps; ++s) {
          const int shift = (s + 1) / 2 * (s % 2 == 1 ? 1 : -1);  // 0, +1, -1, +2, -2, ...
          at = even.plane(a, i) + shift * step;
          const double distance = plane_clearance(surface, grid, a, i, 0.5 * clearance);
          if (distance > best_distance) {
            best_distance = distance;
            best = at;
          }
          if (distance >= clearance) break;
        }
        at = best;
        moved = moved || at != before;
      }
    if (!moved) break;
  }
  return grid;
}

std::array<int, 3> tile_counts(const Box& domain, int tiles) {
  if (tiles < 1 || tiles > kMaxTiles)
    throw SettingError("tiles", "the number of tiles must be in 1.." + std::to_string(kMaxTiles));
  std::array<int, 3> counts{1, 1, 1};
  // Double the count along the axis whose tiles are longest until there are enough.
  while (counts[0] * counts[1] * counts[2] < tiles) {
    int longest = 0;
    for (int a = 1; a < 3; ++a)
      if (domain.size()[a] / counts[static_cast<std::size_t>(a)] >
          domain.size()[longest] / counts[static_cast<std::size_t>(longest)])
        longest = a;
    counts[static_cast<std::size_t>(longest)] *= 2;
  }
  return counts;
}

std::array<TileFace, 6> tile_faces(const std::array<int, 3>& tile) {
  std::array<TileFace, 6> faces;
  for (int a = 0; a < 3; ++a) {
    const std::array<int, 2> cell{tile[static_cast<std::size_t>((a + 1) % 3)],
                                  tile[static_cast<std::size_t>((a + 2) % 3)]};
    faces[static_cast<std::size_t>(2 * a)] = {a, tile[static_cast<std::size_t>(a)], cell};
    faces[static_cast<std::size_t>(2 * a + 1)] = {a, tile[static_cast<std::size_t>(a)] + 1, cell};
  }
  return faces;
}

std::vector<TileFace> grid_faces(const TileGrid& grid) {
  std::vector<TileFace> faces;
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int i = 0; i <= grid.counts[static_cast<std::size_t>(a)]; ++i)
      for (int j = 0; j < grid.counts[static_cast<std::size_t>(u)]; ++j)
        for (int k = 0; k < grid.counts[static_cast<std::size_t>(v)]; ++k) faces.push_back({a, i, {j, k}});
  }
  return faces;
}

}  // namespace isopatch
