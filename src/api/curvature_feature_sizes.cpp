// The search for places where f = 0 turns within an edge (curvature_feature_sizes.hpp).
#include "api/curvature_feature_sizes.hpp"

#include <isopatch/error.hpp>
#include <isopatch/level_set_curvature.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

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
/// hold the zero vector. With k the axis whose component is farthest from 0, every gradient lies within
/// atan(|other components|max / |g_k|min) of that axis.
std::optional<double> cone_opening(const std::array<Interval, 3>& g) {
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (mignitude(g[static_cast<std::size_t>(a)]) > mignitude(g[static_cast<std::size_t>(k)])) k = a;
  const double m = mignitude(g[static_cast<std::size_t>(k)]);
  if (!(m > 0.0)) return std::nullopt;
  double t2 = 0.0;
  for (int a = 0; a < 3; ++a)
    if (a != k) t2 += magnitude(g[static_cast<std::size_t>(a)]) * magnitude(g[static_cast<std::size_t>(a)]);
  return 2.0 * std::atan(std::sqrt(t2) / m);
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

/// Cubes of side `side` covering box, clipped to it (z, y, x ascending).
std::vector<Box> starting_cubes(const Box& box, double side) {
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a)
    n[static_cast<std::size_t>(a)] = std::max(1, static_cast<int>(std::ceil(box.size()[a] / side - 1e-9)));
  std::vector<Box> cubes;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Vec3 lo = box.lo + side * Vec3(i, j, k);
        cubes.push_back(Box{lo, (lo + Vec3::Constant(side)).cwiseMin(box.hi)});
      }
  return cubes;
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
  std::vector<Box> level = starting_cubes(box, side);
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
