// The tricubic B-spline interpolant of a sampled volume as a Surface (volume_surface.hpp).
#include <isopatch/error.hpp>
#include <isopatch/volume_surface.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>

#include "core/short_number.hpp"
#include "sampled/bspline.hpp"
#include "sampled/coefficient_bounds.hpp"
#include "sampled/spline_surface.hpp"
#include "volume/mapped_file.hpp"
#include "volume/npy_reader.hpp"

namespace isopatch {

namespace {

/// Coefficients of a grid, in C order, and what keeps them alive (a vector, or a mapped file).
struct Coefficients {
  const double* data = nullptr;
  std::shared_ptr<const void> owner;
};

/// The runs of consecutive values among `indices` (sorted and deduplicated here).
std::vector<bspline::IndexRange> runs(std::vector<std::size_t> indices) {
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  std::vector<bspline::IndexRange> out;
  for (const std::size_t i : indices) {
    if (!out.empty() && out.back().hi + 1 == i)
      out.back().hi = i;
    else
      out.push_back({i, i});
  }
  return out;
}

/// Calls `f` with every box of one run per axis.
template <class F>
void for_each_box(const std::vector<bspline::IndexRange>& x, const std::vector<bspline::IndexRange>& y,
                  const std::vector<bspline::IndexRange>& z, F&& f) {
  for (const auto& a : x)
    for (const auto& b : y)
      for (const auto& c : z) f(bspline::IndexBox{a, b, c});
}

/// Boxes of at most this many coefficients (with repeats) are scanned; larger ones use the brick
/// summaries (both give the same extremes).
constexpr std::size_t kScanned = 4096;

class VolumeSurface final : public bspline::SplineSurface<VolumeSurface> {
 public:
  VolumeSurface(const Volume& grid, Coefficients coefficients, double level, std::string name)
      : SplineSurface(std::move(name), grid.extent()),
        shape_(grid.shape),
        spacing_(grid.spacing),
        origin_(grid.origin),
        level_(level),
        coefficients_(std::move(coefficients)) {}

 private:
  friend class bspline::SplineSurface<VolumeSurface>;

  double coefficient(std::size_t i, std::size_t j, std::size_t k) const {
    return coefficients_.data[(i * shape_[1] + j) * shape_[2] + k];
  }

  /// Value (order 0), with gradient (1), with Hessian (2), of s - level at p.
  template <int Order>
  SecondOrder evaluate(const Vec3& p) const {
    std::array<std::array<std::size_t, 4>, 3> index;
    std::array<bspline::Weights, 3> w;
    for (int a = 0; a < 3; ++a) {
      const double u = (p[a] - origin_[a]) / spacing_[a];
      // Far outside, the mirror repeats the grid; a NaN or huge coordinate gives NaN, which callers check.
      if (!(std::abs(u) < 1e15)) {
        SecondOrder s;
        s.value = std::numeric_limits<double>::quiet_NaN();
        return s;
      }
      const double cell = std::floor(u);
      w[static_cast<std::size_t>(a)] = bspline::weights(u - cell);
      const auto base = static_cast<std::int64_t>(cell) - 1;
      for (int m = 0; m < 4; ++m)
        index[static_cast<std::size_t>(a)][static_cast<std::size_t>(m)] =
            bspline::mirror(base + m, shape_[static_cast<std::size_t>(a)]);
    }
    SecondOrder s = bspline::tricubic<Order>(w, [&](std::size_t a, std::size_t b, std::size_t c) {
      return coefficient(index[0][a], index[1][b], index[2][c]);
    });
    s.value -= level_;
    bspline::to_world(s, spacing_);
    return s;
  }

  /// Convex-hull bounds over `box`: the coefficients whose basis functions reach it (cells
  /// floor(u_lo) .. floor(u_hi), coefficients one before to two after), and with `gradient` the
  /// differences of neighbours among them along each axis.
  IntervalGradient hull(const Box& box, bool gradient) const {
    IntervalGradient r;
    std::array<std::vector<std::size_t>, 3> index;
    for (int a = 0; a < 3; ++a) {
      const std::size_t n = shape_[static_cast<std::size_t>(a)];
      const double lo = (box.lo[a] - origin_[a]) / spacing_[a], hi = (box.hi[a] - origin_[a]) / spacing_[a];
      if (!(std::abs(lo) < 1e12 && std::abs(hi) < 1e12 && lo <= hi)) return r;  // unbounded
      const auto first = static_cast<std::int64_t>(std::floor(lo)) - 1;
      const auto last = static_cast<std::int64_t>(std::floor(hi)) + 2;
      auto& axis = index[static_cast<std::size_t>(a)];
      // Beyond a whole period of the mirror (2 (n - 1) indices) nothing new is reached.
      const std::int64_t end = std::min(last, first + 2 * static_cast<std::int64_t>(n) + 1);
      for (std::int64_t i = first; i <= end; ++i) axis.push_back(bspline::mirror(i, n));
    }
    const double inf = std::numeric_limits<double>::infinity();
    double vlo = inf, vhi = -inf;
    std::array<double, 3> glo{inf, inf, inf}, ghi{-inf, -inf, -inf};
    if (index[0].size() * index[1].size() * index[2].size() <= kScanned)
      scan_hull(index, gradient, vlo, vhi, glo, ghi);
    else
      summary_hull(index, gradient, vlo, vhi, glo, ghi);
    // Rounding in a sum of 64 products of these coefficients: a relative margin far above it keeps the
    // bounds sound.
    const double slack = 1e-12 * (std::max(std::abs(vlo), std::abs(vhi)) + std::abs(level_));
    r.value = {vlo - level_ - slack, vhi - level_ + slack};
    if (gradient)
      for (int g = 0; g < 3; ++g) {
        const auto gi = static_cast<std::size_t>(g);
        r.gradient[gi] = {(glo[gi] - slack) / spacing_[g], (ghi[gi] + slack) / spacing_[g]};
      }
    return r;
  }

  /// The hull's extremes by visiting every coefficient of the mirrored index lists (small boxes).
  void scan_hull(const std::array<std::vector<std::size_t>, 3>& index, bool gradient, double& vlo,
                 double& vhi, std::array<double, 3>& glo, std::array<double, 3>& ghi) const {
    for (std::size_t a = 0; a < index[0].size(); ++a)
      for (std::size_t b = 0; b < index[1].size(); ++b)
        for (std::size_t c = 0; c < index[2].size(); ++c) {
          const double v = coefficient(index[0][a], index[1][b], index[2][c]);
          vlo = std::min(vlo, v);
          vhi = std::max(vhi, v);
          if (!gradient) continue;
          const double d[3] = {
              a + 1 < index[0].size() ? coefficient(index[0][a + 1], index[1][b], index[2][c]) - v : 0.0,
              b + 1 < index[1].size() ? coefficient(index[0][a], index[1][b + 1], index[2][c]) - v : 0.0,
              c + 1 < index[2].size() ? coefficient(index[0][a], index[1][b], index[2][c + 1]) - v : 0.0};
          const bool has[3] = {a + 1 < index[0].size(), b + 1 < index[1].size(), c + 1 < index[2].size()};
          for (int g = 0; g < 3; ++g)
            if (has[g]) {
              glo[static_cast<std::size_t>(g)] = std::min(glo[static_cast<std::size_t>(g)], d[g]);
              ghi[static_cast<std::size_t>(g)] = std::max(ghi[static_cast<std::size_t>(g)], d[g]);
            }
        }
  }

  /// The same extremes from the brick summaries (large boxes). The coefficients reached are boxes of
  /// runs of indices; a difference of neighbours along an axis is c[p + 1] - c[p] where the mirrored
  /// indices go up at p, and its negative where they go down.
  void summary_hull(const std::array<std::vector<std::size_t>, 3>& index, bool gradient, double& vlo,
                    double& vhi, std::array<double, 3>& glo, std::array<double, 3>& ghi) const {
    std::array<std::vector<bspline::IndexRange>, 3> reached, up, down;
    for (std::size_t a = 0; a < 3; ++a) {
      const auto& axis = index[a];
      reached[a] = runs(std::vector<std::size_t>(axis));
      if (!gradient) continue;
      std::vector<std::size_t> rising, falling;
      for (std::size_t t = 0; t + 1 < axis.size(); ++t)
        (axis[t + 1] > axis[t] ? rising : falling).push_back(std::min(axis[t], axis[t + 1]));
      up[a] = runs(std::move(rising));
      down[a] = runs(std::move(falling));
    }
    const bspline::CoefficientBounds& summary = bounds();
    for_each_box(reached[0], reached[1], reached[2], [&](const bspline::IndexBox& b) {
      const auto [lo, hi] = summary.values(b);
      vlo = std::min(vlo, lo);
      vhi = std::max(vhi, hi);
    });
    if (gradient)
      for (std::size_t g = 0; g < 3; ++g) {
        for (const double sign : {1.0, -1.0}) {
          std::array<const std::vector<bspline::IndexRange>*, 3> along{};
          for (std::size_t a = 0; a < 3; ++a) along[a] = a != g ? &reached[a] : sign > 0 ? &up[g] : &down[g];
          for_each_box(*along[0], *along[1], *along[2], [&](const bspline::IndexBox& b) {
            const auto [lo, hi] = summary.differences(static_cast<int>(g), b);
            glo[g] = std::min(glo[g], sign > 0 ? lo : -hi);
            ghi[g] = std::max(ghi[g], sign > 0 ? hi : -lo);
          });
        }
      }
  }

  std::array<std::size_t, 3> shape_;
  Vec3 spacing_;
  Vec3 origin_;
  double level_;
  Coefficients coefficients_;
  mutable std::once_flag bounds_made_;
  mutable std::unique_ptr<bspline::CoefficientBounds> bounds_;  // made by the first bound asked for

  const bspline::CoefficientBounds& bounds() const {
    std::call_once(bounds_made_, [this] {
      bounds_ = std::make_unique<bspline::CoefficientBounds>(coefficients_.data, shape_);
    });
    return *bounds_;
  }
};

}  // namespace

void interpolating_coefficients(std::span<double> samples, const std::array<std::size_t, 3>& shape) {
  std::size_t count = 1;
  for (const std::size_t n : shape) {
    if (n < 2) throw InputError("every side of a volume needs at least 2 samples", "volume");
    if (count > std::numeric_limits<std::size_t>::max() / n)
      throw InputError("the volume's shape overflows", "volume");
    count *= n;
  }
  if (samples.size() != count) throw InputError("the samples do not fill the volume's shape", "volume");
  bspline::interpolating_coefficients(samples, shape);
}

SurfacePtr volume_surface(Volume volume, double level, std::string name) {
  volume.validate();
  if (!std::isfinite(level)) throw InputError("the level must be finite", "level");
  const auto [lo, hi] = std::minmax_element(volume.samples.begin(), volume.samples.end());
  if (!(*lo < level) || !(*hi >= level))
    throw NoSurfaceError("no sample of the volume crosses level " + short_number(level) +
                         " (the samples range over [" + short_number(*lo) + ", " + short_number(*hi) + "])");
  auto samples = std::make_shared<std::vector<double>>(std::move(volume.samples));
  bspline::interpolating_coefficients(*samples, volume.shape);
  Coefficients coefficients{samples->data(), samples};
  return std::make_shared<VolumeSurface>(volume, std::move(coefficients), level, std::move(name));
}

SurfacePtr mapped_volume_surface(const std::string& path, const Vec3& spacing, const Vec3& origin,
                                 double level, std::string name) {
  Volume grid;  // no samples: the shape, spacing and origin
  grid.spacing = spacing;
  grid.origin = origin;
  auto file = std::make_shared<volume_io::MappedFile>(path);
  const volume_io::NpyLayout layout = volume_io::read_npy_layout(file->bytes(), path, kMaxMappedSamples);
  if (layout.descr != "<f8" || layout.fortran_order)
    throw IoError(path + ": B-spline coefficients must be little-endian float64 in C order ('<f8'), not " +
                  layout.descr + (layout.fortran_order ? " in Fortran order" : ""));
  for (const std::size_t n : layout.shape)
    if (n < 2) throw IoError(path + ": every side of the coefficient grid needs at least 2 samples");
  if (layout.data_offset % alignof(double) != 0)
    throw IoError(path + ": the coefficients do not start at a multiple of 8 bytes");
  grid.shape = layout.shape;
  grid.validate_geometry();
  if (!std::isfinite(level)) throw InputError("the level must be finite", "level");
  Coefficients coefficients{reinterpret_cast<const double*>(file->bytes().data() + layout.data_offset), file};
  return std::make_shared<VolumeSurface>(grid, std::move(coefficients), level, std::move(name));
}

}  // namespace isopatch
