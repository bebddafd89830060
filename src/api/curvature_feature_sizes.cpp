// The search for places where f = 0 turns within an edge (curvature_feature_sizes.hpp).
#include "api/curvature_feature_sizes.hpp"

#include <isopatch/error.hpp>
#include <isopatch/level_set_curvature.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <tuple>

#include "surface/project_point.hpp"
#include "surface/sampler.hpp"

namespace isopatch {
namespace {

/// The smallest |x| over an interval (0 when it holds 0) and the largest.
double mignitude(const Interval& i) {
  return i.contains_zero() ? 0.0 : std::min(std::abs(i.lo), std::abs(i.hi));
}
double magnitude(const Interval& i) {
  return std::max(std::abs(i.lo), std::abs(i.hi));
}

/// An upper bound of the angle between any two gradients in the box g (radians), or nullopt when g may
/// hold the zero vector. Two bounds, the smaller kept: with k the axis whose component is farthest from
/// 0, every gradient lies within atan(|other components|max / |g_k|min) of that axis; and every
/// gradient lies within asin(r / |m|) of the box's middle m, r the box's half diagonal (the first is
/// loose for a normal between the axes, the second for a wide box). Both are slightly widened for
/// rounding.
std::optional<double> cone_opening(const std::array<Interval, 3>& g) {
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (mignitude(g[static_cast<std::size_t>(a)]) > mignitude(g[static_cast<std::size_t>(k)])) k = a;
  const double m = mignitude(g[static_cast<std::size_t>(k)]);
  if (!(m > 0.0)) return std::nullopt;
  double t2 = 0.0;
  for (int a = 0; a < 3; ++a)
    if (a != k) t2 += magnitude(g[static_cast<std::size_t>(a)]) * magnitude(g[static_cast<std::size_t>(a)]);
  const double about_axis = 2.0 * std::atan(std::sqrt(t2) / m);
  double middle2 = 0.0, radius2 = 0.0;
  for (const Interval& c : g) {
    const double middle = 0.5 * c.lo + 0.5 * c.hi, radius = 0.5 * c.hi - 0.5 * c.lo;
    middle2 += middle * middle;
    radius2 += radius * radius;
  }
  const double r = std::sqrt(radius2) * (1.0 + 1e-9), mid = std::sqrt(middle2) * (1.0 - 1e-9);
  const double about_middle = r < mid ? 2.0 * std::asin(r / mid) : std::numbers::pi;
  return std::min(about_axis, about_middle) * (1.0 + 1e-9);
}

/// What one cube asks for: to be split, a source, or nothing.
struct CubeOutcome {
  bool split = false;
  std::optional<SizeSource> source;
};

/// The eight halves of b (z, y, x ascending).
std::array<Box, 8> octants(const Box& b) {
  const Vec3 mid = 0.5 * (b.lo + b.hi);
  std::array<Box, 8> out;
  for (int i = 0; i < 8; ++i) {
    Box c = b;
    for (int a = 0; a < 3; ++a) {
      if ((i >> a) & 1)
        c.lo[a] = mid[a];
      else
        c.hi[a] = mid[a];
    }
    out[static_cast<std::size_t>(i)] = c;
  }
  return out;
}

class Search {
 public:
  Search(const Surface& surface, double edge, double smallest, const CurvatureFeatureParams& p)
      : surface_(surface), f_(surface), edge_(edge), smallest_(smallest), p_(p) {}

  /// What `cube` asks for; past the search's budget (may_split false) it is measured where it is.
  CubeOutcome examine(const Box& cube, bool may_split = true) const {
    CubeOutcome out;
    const std::optional<IntervalGradient> g = surface_.gradient_bound(cube);
    if (!g || !g->value.contains_zero()) return out;
    const double side = cube.size().maxCoeff();
    const std::optional<double> opening = cone_opening(g->gradient);
    if (!opening) return out;  // grad f may vanish: the singular-point search's business
    // A cube may turn by `turn` per relevant length (the largest size a source may ask for), up to
    // coarse_turn times that: only a turn within less than that length asks for a source.
    const double allowed = p_.turn * std::clamp(side / (p_.relevant * edge_), 1.0, p_.coarse_turn);
    // The enclosure of grad f may be far wider than its range (high degrees, repeated variables): a
    // cube is split only when the gradients sampled at its corners and centre spread as widely too.
    // (The samples never spread wider than the enclosure's bound: where it allows the turn, they are
    // not sampled.)
    if (may_split && *opening > allowed && side > p_.finest_share * edge_ &&
        sampled_opening(cube) > allowed) {
      out.split = true;
      return out;
    }
    if (side < edge_) out.source = source_in(cube);
    return out;
  }

 private:
  /// The largest angle between the normalised gradients at the cube's 8 corners and its centre
  /// (pi where one of them vanishes or is not finite).
  double sampled_opening(const Box& cube) const {
    std::array<Vec3, 9> n;
    for (int i = 0; i < 9; ++i) {
      Vec3 p = 0.5 * (cube.lo + cube.hi);
      if (i < 8)
        for (int a = 0; a < 3; ++a) p[a] = ((i >> a) & 1) ? cube.hi[a] : cube.lo[a];
      const Vec3 g = surface_.value_gradient(p).gradient;
      const double length = g.norm();
      if (!(length > 0.0) || !std::isfinite(length)) return std::numbers::pi;
      n[static_cast<std::size_t>(i)] = g / length;
    }
    double smallest_cosine = 1.0;
    for (std::size_t i = 0; i < 9; ++i)
      for (std::size_t j = i + 1; j < 9; ++j) smallest_cosine = std::min(smallest_cosine, n[i].dot(n[j]));
    return std::acos(std::clamp(smallest_cosine, -1.0, 1.0));
  }

  /// The size asked for at the point of f = 0 nearest the cube's centre, when it lies in the cube.
  std::optional<SizeSource> source_in(const Box& cube) const {
    const double side = cube.size().maxCoeff();
    Vec3 p = 0.5 * (cube.lo + cube.hi);
    try {
      if (!project_to_surface(f_, p, 1e-6 * side, side)) return std::nullopt;
    } catch (const EvaluationError&) {
      return std::nullopt;
    }
    if (!cube.contains(p, 1e-9 * side)) return std::nullopt;
    const double kappa = max_abs_principal_curvature(surface_, p);
    if (!std::isfinite(kappa) || kappa <= 0.0) return std::nullopt;
    const double size = std::max(smallest_, p_.turn / kappa);
    if (!(size < p_.relevant * edge_)) return std::nullopt;
    return SizeSource{p, size, p_.grading};
  }

  const Surface& surface_;
  Sampler f_;
  double edge_, smallest_;
  CurvatureFeatureParams p_;
};

/// The grid of cubes of side `side` from box.lo, clipped to the box.
struct CubeGrid {
  Box box;
  double side = 0.0;
  std::array<int, 3> count{};

  CubeGrid(const Box& b, double s) : box(b), side(s) {
    for (int a = 0; a < 3; ++a)
      count[static_cast<std::size_t>(a)] =
          std::max(1, static_cast<int>(std::ceil(box.size()[a] / side - 1e-9)));
  }
  /// Cube (i, j, k).
  Box cube(const std::array<int, 3>& c) const {
    const Vec3 lo = box.lo + side * Vec3(c[0], c[1], c[2]);
    return Box{lo, (lo + Vec3::Constant(side)).cwiseMin(box.hi)};
  }
};

/// A block of the grid's cubes: [lo, hi) on each axis.
struct CubeBlock {
  std::array<int, 3> lo{}, hi{};
  bool single() const { return hi[0] - lo[0] == 1 && hi[1] - lo[1] == 1 && hi[2] - lo[2] == 1; }
  /// The box holding its cubes (made of their own corners, so that it holds each cube exactly).
  Box box(const CubeGrid& grid) const {
    return Box{grid.cube(lo).lo, grid.cube({hi[0] - 1, hi[1] - 1, hi[2] - 1}).hi};
  }
  /// Its two halves across its longest axis (in cubes).
  std::array<CubeBlock, 2> halves() const {
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[static_cast<std::size_t>(a)] - lo[static_cast<std::size_t>(a)] >
          hi[static_cast<std::size_t>(axis)] - lo[static_cast<std::size_t>(axis)])
        axis = a;
    const auto ax = static_cast<std::size_t>(axis);
    CubeBlock first = *this, second = *this;
    first.hi[ax] = second.lo[ax] = lo[ax] + (hi[ax] - lo[ax]) / 2;
    return {first, second};
  }
};

/// The cubes of `grid` that may ask for a source, in z, y, x order: blocks of cubes halved from the whole
/// grid down, kept where the enclosure of f over the block holds 0 and the enclosure of grad f lets
/// the normals turn by more than the block's cubes allow (or may vanish), so that the work follows
/// the surface's turns instead of the box's volume in cubes. A dropped block's cubes could not ask for
/// anything: without a zero of f (the enclosure is rigorous) a cube has no point of f = 0 to measure, and a
/// cube of the grid is split only when its own enclosure of grad f, inside the block's (enclosures
/// only narrow on a smaller box), opens by more than it allows; one that is not split asks for nothing
/// when it is wider than an edge (blocks with a narrower cube are kept). So the sources are those of
/// examining every cube. Where f has no enclosure, every cube.
std::vector<Box> cubes_near_surface(const Surface& surface, const CubeGrid& grid,
                                    const CurvatureFeatureParams& p, double edge) {
  std::vector<CubeBlock> blocks{CubeBlock{{0, 0, 0}, grid.count}}, cubes;
  while (!blocks.empty()) {
    std::vector<std::uint8_t> keep(blocks.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 64), [&](const auto& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const std::optional<IntervalGradient> g = surface.gradient_bound(blocks[i].box(grid));
        if (!g) {
          keep[i] = 1;
          continue;
        }
        // The block's cube of the highest indices is the smallest (only the last layers are clipped by
        // the box): the smallest turn a cube of the block allows, and a cube narrower than an edge
        // measures a source without being split, so such a block is kept.
        const double smallest =
            grid.cube({blocks[i].hi[0] - 1, blocks[i].hi[1] - 1, blocks[i].hi[2] - 1}).size().maxCoeff();
        const double allowed = p.turn * std::clamp(smallest / (p.relevant * edge), 1.0, p.coarse_turn);
        const std::optional<double> opening = cone_opening(g->gradient);
        keep[i] = g->value.contains_zero() && (smallest < edge || !opening || *opening > allowed) ? 1 : 0;
      }
    });
    std::vector<CubeBlock> next;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      if (keep[i] == 0) continue;
      if (blocks[i].single())
        cubes.push_back(blocks[i]);
      else
        for (const CubeBlock& half : blocks[i].halves()) next.push_back(half);
    }
    blocks = std::move(next);
  }
  std::sort(cubes.begin(), cubes.end(), [](const CubeBlock& a, const CubeBlock& b) {
    return std::tie(a.lo[2], a.lo[1], a.lo[0]) < std::tie(b.lo[2], b.lo[1], b.lo[0]);
  });
  std::vector<Box> boxes(cubes.size());
  for (std::size_t i = 0; i < cubes.size(); ++i) boxes[i] = grid.cube(cubes[i].lo);
  return boxes;
}

}  // namespace

CurvatureFeatureSearch curvature_feature_sources(const Surface& surface, const Box& box, double edge,
                                                 double smallest, const CurvatureFeatureParams& params) {
  CurvatureFeatureSearch result;
  if (!surface.gradient_bound(box)) return result;
  result.searched = true;
  const Search search(surface, edge, smallest, params);
  // The starting cubes are at most max_cells, so a tiny edge in a large box stays bounded.
  const double side = std::max(params.start_edges * edge,
                               std::cbrt(box.size().prod() / static_cast<double>(params.max_cells)));
  std::vector<Box> level = cubes_near_surface(surface, CubeGrid(box, side), params, edge);
  while (!level.empty()) {
    std::vector<CubeOutcome> outcomes(level.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, level.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i)
                          outcomes[i] = search.examine(level[i]);
                      });
    std::vector<Box> next;
    for (std::size_t i = 0; i < level.size(); ++i) {
      const CubeOutcome& o = outcomes[i];
      if (o.source) result.sources.push_back(*o.source);
      if (o.split)
        for (const Box& c : octants(level[i])) next.push_back(c);
    }
    // Past the budget the search stops: the cubes still to split are measured where they are.
    if (next.size() > params.max_cells) {
      for (std::size_t i = 0; i < level.size(); ++i) {
        if (!outcomes[i].split) continue;
        if (const CubeOutcome o = search.examine(level[i], false); o.source)
          result.sources.push_back(*o.source);
      }
      break;
    }
    level = std::move(next);
  }
  return result;
}

}  // namespace isopatch
