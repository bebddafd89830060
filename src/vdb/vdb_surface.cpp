// OpenVDB grids as surfaces (vdb_surface.hpp): the sparse B-spline of a grid behind the Surface interface.
#include <isopatch/error.hpp>
#include <isopatch/vdb_surface.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>

#include "core/short_number.hpp"
#include "sampled/spline_surface.hpp"
#include "vdb/sparse_bspline.hpp"
#include "vdb/vdb_reader.hpp"

namespace isopatch {

namespace {

class VdbSurface final : public bspline::SplineSurface<VdbSurface> {
 public:
  VdbSurface(std::string name, const Box& box, vdb::SparseSamples&& samples, const VdbSource& source)
      : SplineSurface(std::move(name), box),
        spacing_(samples.spacing),
        origin_(samples.origin),
        level_(source.level),
        sign_(source.inside_above ? -1.0 : 1.0),
        spline_(std::move(samples), source.level) {}

  std::size_t bytes() const { return spline_.bytes(); }

 private:
  friend class bspline::SplineSurface<VdbSurface>;

  template <int Order>
  SecondOrder evaluate(const Vec3& p) const {
    std::array<double, 3> u{};
    for (int a = 0; a < 3; ++a) {
      u[static_cast<std::size_t>(a)] = (p[a] - origin_[a]) / spacing_[a];
      // A NaN or huge coordinate gives NaN, which callers check (as a .npy volume's surface does).
      if (!(std::abs(u[static_cast<std::size_t>(a)]) < 1e15)) {
        SecondOrder s;
        s.value = std::numeric_limits<double>::quiet_NaN();
        return s;
      }
    }
    SecondOrder s = spline_.evaluate<Order>(u);
    s.value -= level_;
    bspline::to_world(s, spacing_);
    if (sign_ < 0.0) {
      s.value = -s.value;
      s.gradient = -s.gradient;
      s.hessian = -s.hessian;
    }
    return s;
  }

  /// Convex-hull bounds over `box`: coefficients of the cells floor(u_lo) .. floor(u_hi), one before to
  /// two after.
  IntervalGradient hull(const Box& box, bool gradient) const {
    IntervalGradient r;
    vdb::Coord lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      const double l = (box.lo[a] - origin_[a]) / spacing_[a], h = (box.hi[a] - origin_[a]) / spacing_[a];
      if (!(std::abs(l) < 1e12 && std::abs(h) < 1e12 && l <= h)) return r;  // unbounded
      lo[static_cast<std::size_t>(a)] = static_cast<std::int64_t>(std::floor(l)) - 1;
      hi[static_cast<std::size_t>(a)] = static_cast<std::int64_t>(std::floor(h)) + 2;
    }
    const vdb::SparseBspline::Hull c = spline_.hull(lo, hi, gradient);
    // Rounding in a sum of 64 products: a relative margin far above it keeps the bounds sound.
    const double slack = 1e-12 * (std::max(std::abs(c.lo), std::abs(c.hi)) + std::abs(level_));
    const auto oriented = [this](double l, double h) {
      return sign_ > 0.0 ? Interval{l, h} : Interval{-h, -l};
    };
    r.value = oriented(c.lo - level_ - slack, c.hi - level_ + slack);
    if (gradient)
      for (std::size_t g = 0; g < 3; ++g)
        r.gradient[g] = oriented((c.dlo[g] - slack) / spacing_[static_cast<int>(g)],
                                 (c.dhi[g] + slack) / spacing_[static_cast<int>(g)]);
    return r;
  }

  Vec3 spacing_;
  Vec3 origin_;
  double level_;
  double sign_;
  vdb::SparseBspline spline_;
};

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

SurfacePtr make_surface(vdb::SparseSamples samples, const VdbSource& source, const std::string& file,
                        const std::string& grid) {
  const std::string where = file + ": grid '" + grid + "'";
  if (!std::isfinite(source.level)) throw InputError("the level must be finite", "level");
  if (samples.active_voxels == 0) throw NoSurfaceError(where + " has no active voxels");
  double lo = samples.tiles.background, hi = samples.tiles.background;
  samples.tiles.for_each_value([&](double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  });
  for (const auto& [key, values] : samples.leaves) {
    const auto [l, h] = std::minmax_element(values.begin(), values.end());
    lo = std::min(lo, *l);
    hi = std::max(hi, *h);
  }
  if (!(lo < source.level) || !(hi >= source.level))
    throw NoSurfaceError(where + ": no value crosses level " + short_number(source.level) +
                         " (the values range over [" + short_number(lo) + ", " + short_number(hi) + "])");
  Box box;
  for (int a = 0; a < 3; ++a) {
    const auto i = static_cast<std::size_t>(a);
    box.lo[a] = samples.origin[a] + static_cast<double>(samples.active_lo[i]) * samples.spacing[a];
    box.hi[a] = samples.origin[a] + static_cast<double>(samples.active_hi[i]) * samples.spacing[a];
    if (!(box.hi[a] > box.lo[a])) {  // one voxel thick: a voxel on either side
      box.lo[a] -= samples.spacing[a];
      box.hi[a] += samples.spacing[a];
    }
  }
  const std::string name = base_name(file) + (grid.empty() ? "" : ":" + grid);
  return std::make_shared<VdbSurface>(name, box, std::move(samples), source);
}

}  // namespace

bool is_vdb_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".vdb";
}

std::vector<VdbGridInfo> vdb_grids(const std::string& path) {
  return vdb::list_grids(path);
}

SurfacePtr vdb_surface(const std::string& path, const VdbSource& source) {
  std::string grid;
  vdb::SparseSamples samples = vdb::read_grid(path, source.grid, grid);
  return make_surface(std::move(samples), source, path, grid);
}

SurfacePtr decode_vdb_surface(std::string_view bytes, const VdbSource& source, const std::string& name) {
  std::string grid;
  vdb::SparseSamples samples = vdb::decode_grid(bytes, source.grid, name, grid);
  return make_surface(std::move(samples), source, name, grid);
}

std::size_t vdb_surface_bytes(const Surface& surface) {
  const auto* vdb = dynamic_cast<const VdbSurface*>(&surface);
  return vdb ? vdb->bytes() : 0;
}

}  // namespace isopatch
