// The sparse tricubic B-spline of a .vdb grid (sparse_bspline.hpp).
#include "vdb/sparse_bspline.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <set>

namespace isopatch::vdb {

namespace {

constexpr std::int64_t kPadded = kBrick + 2;          // a brick with one voxel of neighbours on every side
constexpr std::size_t kScannedSlots = 32768;          // boxes over more brick positions visit the brick list
constexpr std::uint64_t kScannedCoefficients = 4096;  // boxes of at most this many are scanned coefficient
                                                      // by coefficient (exact hulls; summaries beyond)

Coord brick_of(const Coord& v) {
  return {floor_shift(v[0], kBrickShift), floor_shift(v[1], kBrickShift), floor_shift(v[2], kBrickShift)};
}

/// The samples of `brick` with one voxel around it, x slowest: each of the 27 bricks it touches looked up
/// once (a leaf's values, or a constant: a tile covers whole bricks).
std::vector<double> padded_samples(const SparseSamples& samples, const Coord& brick) {
  std::array<const std::vector<double>*, 27> leaf{};
  std::array<double, 27> constant{};
  for (std::size_t n = 0; n < 27; ++n) {
    const Coord key{brick[0] + static_cast<std::int64_t>(n / 9) - 1,
                    brick[1] + static_cast<std::int64_t>(n / 3 % 3) - 1,
                    brick[2] + static_cast<std::int64_t>(n % 3) - 1};
    const auto it = samples.leaves.find(key);
    if (it != samples.leaves.end())
      leaf[n] = &it->second;
    else
      constant[n] = samples.tiles.value({key[0] * kBrick, key[1] * kBrick, key[2] * kBrick});
  }
  std::vector<double> out(static_cast<std::size_t>(kPadded * kPadded * kPadded));
  const auto part = [](std::int64_t p) { return p == 0 ? 0 : p <= kBrick ? 1 : 2; };
  for (std::int64_t x = 0; x < kPadded; ++x)
    for (std::int64_t y = 0; y < kPadded; ++y)
      for (std::int64_t z = 0; z < kPadded; ++z) {
        const auto n = static_cast<std::size_t>(part(x) * 9 + part(y) * 3 + part(z));
        const Coord v{brick[0] * kBrick + x - 1, brick[1] * kBrick + y - 1, brick[2] * kBrick + z - 1};
        out[static_cast<std::size_t>((x * kPadded + y) * kPadded + z)] =
            leaf[n] ? (*leaf[n])[brick_offset(v)] : constant[n];
      }
  return out;
}

/// One pass of (-1, 8, -1) / 6 along `axis` of a block of `n` = {nx, ny, nz} values, x slowest: the
/// result has two fewer values along that axis.
std::vector<double> filter_axis(const std::vector<double>& in, std::array<std::int64_t, 3>& n, int axis) {
  std::array<std::int64_t, 3> m = n;
  m[static_cast<std::size_t>(axis)] -= 2;
  const std::array<std::int64_t, 3> stride{n[1] * n[2], n[2], 1};
  const std::int64_t step = stride[static_cast<std::size_t>(axis)];
  std::vector<double> out(static_cast<std::size_t>(m[0] * m[1] * m[2]));
  for (std::int64_t x = 0; x < m[0]; ++x)
    for (std::int64_t y = 0; y < m[1]; ++y)
      for (std::int64_t z = 0; z < m[2]; ++z) {
        // The output's (x, y, z) is the input's centre one further along `axis`.
        const std::int64_t centre =
            (x + (axis == 0)) * stride[0] + (y + (axis == 1)) * stride[1] + z + (axis == 2);
        const auto c = static_cast<std::size_t>(centre);
        out[static_cast<std::size_t>((x * m[1] + y) * m[2] + z)] =
            (8.0 * in[c] - in[c - static_cast<std::size_t>(step)] - in[c + static_cast<std::size_t>(step)]) /
            6.0;
      }
  n = m;
  return out;
}

}  // namespace

SparseBspline::SparseBspline(SparseSamples&& samples, double level) : level_(level) {
  std::set<Coord> keys;
  for (const auto& [key, values] : samples.leaves)
    for (std::int64_t n = 0; n < 27; ++n)
      keys.insert({key[0] + n / 9 - 1, key[1] + n / 3 % 3 - 1, key[2] + n % 3 - 1});
  keys_.assign(keys.begin(), keys.end());
  index_.reserve(keys_.size());
  for (std::size_t i = 0; i < keys_.size(); ++i) index_.emplace(keys_[i], static_cast<std::uint32_t>(i));
  coefficients_.resize(keys_.size() * kBrickVoxels);
  tbb::parallel_for(std::size_t{0}, keys_.size(), [&](std::size_t i) {
    std::array<std::int64_t, 3> n{kPadded, kPadded, kPadded};
    std::vector<double> block = padded_samples(samples, keys_[i]);
    for (int axis = 2; axis >= 0; --axis) block = filter_axis(block, n, axis);
    std::transform(block.begin(), block.end(),
                   coefficients_.begin() + static_cast<std::ptrdiff_t>(i * kBrickVoxels),
                   [](double c) { return static_cast<float>(c); });
  });
  samples.tiles.for_each_value([this](double v) {
    Side& side = sides_[v < level_ ? 0 : 1];
    side.lo = side.present ? std::min(side.lo, v) : v;
    side.hi = side.present ? std::max(side.hi, v) : v;
    side.present = true;
  });
  tiles_ = std::move(samples.tiles);  // what coefficients outside the bricks are from here on
  samples.tiles = {};
  summarise();
}

double SparseBspline::coefficient(const Coord& v) const {
  const float* brick = find(brick_of(v));
  return brick ? static_cast<double>(brick[brick_offset(v)]) : tiles_.value(v);
}

void SparseBspline::summarise() {
  summary_.resize(keys_.size());
  tbb::parallel_for(std::size_t{0}, keys_.size(), [&](std::size_t i) {
    const float* c = &coefficients_[i * kBrickVoxels];
    const Coord base{keys_[i][0] * kBrick, keys_[i][1] * kBrick, keys_[i][2] * kBrick};
    const double inf = std::numeric_limits<double>::infinity();
    Summary s{inf, -inf, {inf, inf, inf}, {-inf, -inf, -inf}};
    for (std::int64_t x = 0; x < kBrick; ++x)
      for (std::int64_t y = 0; y < kBrick; ++y)
        for (std::int64_t z = 0; z < kBrick; ++z) {
          const Coord v{base[0] + x, base[1] + y, base[2] + z};
          const auto value = static_cast<double>(c[brick_offset(v)]);
          s.lo = std::min(s.lo, value);
          s.hi = std::max(s.hi, value);
          const std::array<std::int64_t, 3> local{x, y, z};
          for (std::size_t a = 0; a < 3; ++a) {
            Coord next = v;
            ++next[a];
            const double forward = local[a] + 1 < kBrick ? static_cast<double>(c[brick_offset(next)]) - value
                                                         : coefficient(next) - value;
            s.dlo[a] = std::min(s.dlo[a], forward);
            s.dhi[a] = std::max(s.dhi[a], forward);
            if (local[a] == 0) {  // the difference reaching into the brick from the voxel before it
              Coord before = v;
              --before[a];
              const double backward = value - coefficient(before);
              s.dlo[a] = std::min(s.dlo[a], backward);
              s.dhi[a] = std::max(s.dhi[a], backward);
            }
          }
        }
    summary_[i] = s;
  });
}

void SparseBspline::add_side(Hull& h, const Side& side, bool gradient) const {
  if (!side.present) return;
  h.lo = std::min(h.lo, side.lo);
  h.hi = std::max(h.hi, side.hi);
  if (gradient)
    for (std::size_t a = 0; a < 3; ++a) {  // two neighbours both outside every brick, on this side
      h.dlo[a] = std::min(h.dlo[a], side.lo - side.hi);
      h.dhi[a] = std::max(h.dhi[a], side.hi - side.lo);
    }
}

std::vector<double> SparseBspline::gather(const Coord& lo, const Coord& hi) const {
  const std::array<std::int64_t, 3> n{hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
  std::vector<double> out(static_cast<std::size_t>(n[0] * n[1] * n[2]));
  const Coord blo = brick_of(lo), bhi = brick_of(hi);
  for (std::int64_t bx = blo[0]; bx <= bhi[0]; ++bx)
    for (std::int64_t by = blo[1]; by <= bhi[1]; ++by)
      for (std::int64_t bz = blo[2]; bz <= bhi[2]; ++bz) {
        const float* brick = find({bx, by, bz});
        const double constant = brick ? 0.0 : tiles_.value({bx * kBrick, by * kBrick, bz * kBrick});
        for (std::int64_t x = std::max(lo[0], bx * kBrick); x <= std::min(hi[0], bx * kBrick + kBrick - 1);
             ++x)
          for (std::int64_t y = std::max(lo[1], by * kBrick); y <= std::min(hi[1], by * kBrick + kBrick - 1);
               ++y)
            for (std::int64_t z = std::max(lo[2], bz * kBrick);
                 z <= std::min(hi[2], bz * kBrick + kBrick - 1); ++z)
              out[static_cast<std::size_t>(((x - lo[0]) * n[1] + (y - lo[1])) * n[2] + (z - lo[2]))] =
                  brick ? static_cast<double>(brick[brick_offset({x, y, z})]) : constant;
      }
  return out;
}

SparseBspline::Hull SparseBspline::scan(const Coord& lo, const Coord& hi, bool gradient) const {
  const double inf = std::numeric_limits<double>::infinity();
  Hull h{inf, -inf, {inf, inf, inf}, {-inf, -inf, -inf}};
  const std::vector<double> c = gather(lo, hi);
  const std::array<std::int64_t, 3> n{hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
  const std::array<std::int64_t, 3> stride{n[1] * n[2], n[2], 1};
  for (std::int64_t x = 0; x < n[0]; ++x)
    for (std::int64_t y = 0; y < n[1]; ++y)
      for (std::int64_t z = 0; z < n[2]; ++z) {
        const std::int64_t at = (x * n[1] + y) * n[2] + z;
        const double v = c[static_cast<std::size_t>(at)];
        h.lo = std::min(h.lo, v);
        h.hi = std::max(h.hi, v);
        if (!gradient) continue;
        const std::array<std::int64_t, 3> p{x, y, z};
        for (std::size_t a = 0; a < 3; ++a)
          if (p[a] + 1 < n[a]) {
            const double d = c[static_cast<std::size_t>(at + stride[a])] - v;
            h.dlo[a] = std::min(h.dlo[a], d);
            h.dhi[a] = std::max(h.dhi[a], d);
          }
      }
  for (std::size_t a = 0; a < 3; ++a)
    if (n[a] < 2) h.dlo[a] = h.dhi[a] = 0.0;
  return h;
}

SparseBspline::Hull SparseBspline::hull(const Coord& lo, const Coord& hi, bool gradient) const {
  std::uint64_t count = 1;
  for (std::size_t a = 0; a < 3; ++a)
    count = std::min<std::uint64_t>(count * static_cast<std::uint64_t>(hi[a] - lo[a] + 1),
                                    std::uint64_t{1} << 62);
  if (count <= kScannedCoefficients) return scan(lo, hi, gradient);
  const double inf = std::numeric_limits<double>::infinity();
  Hull h{inf, -inf, {inf, inf, inf}, {-inf, -inf, -inf}};
  const Coord blo = brick_of(lo), bhi = brick_of(hi);
  std::uint64_t slots = 1;
  for (std::size_t a = 0; a < 3; ++a)
    slots = std::min<std::uint64_t>(slots * static_cast<std::uint64_t>(bhi[a] - blo[a] + 1),
                                    std::uint64_t{1} << 62);
  std::uint64_t present = 0;
  std::optional<Coord> absent;  // a brick position in the box without a stored brick
  const auto merge = [&](std::size_t i) {
    const Summary& s = summary_[i];
    h.lo = std::min(h.lo, s.lo);
    h.hi = std::max(h.hi, s.hi);
    for (std::size_t a = 0; a < 3; ++a) {
      h.dlo[a] = std::min(h.dlo[a], s.dlo[a]);
      h.dhi[a] = std::max(h.dhi[a], s.dhi[a]);
    }
    ++present;
  };
  const auto scan_slots = [&](bool merge_present) {  // in order until the first absent one when not merging
    for (std::int64_t x = blo[0]; x <= bhi[0]; ++x)
      for (std::int64_t y = blo[1]; y <= bhi[1]; ++y)
        for (std::int64_t z = blo[2]; z <= bhi[2]; ++z) {
          const auto it = index_.find({x, y, z});
          if (it == index_.end()) {
            if (!absent) absent = Coord{x, y, z};
            if (!merge_present) return;
          } else if (merge_present) {
            merge(it->second);
          }
        }
  };
  if (slots <= kScannedSlots) {
    scan_slots(true);
  } else {
    for (std::size_t i = 0; i < keys_.size(); ++i) {
      const Coord& k = keys_[i];
      if (k[0] >= blo[0] && k[0] <= bhi[0] && k[1] >= blo[1] && k[1] <= bhi[1] && k[2] >= blo[2] &&
          k[2] <= bhi[2])
        merge(i);
    }
    if (present < slots) scan_slots(false);  // finds an absent position within present + 1 probes
  }
  if (!absent) return h;
  // Brick positions without coefficients hold tiles. Bricks reaching both sides of the level: either side's
  // tiles may be there. Else the tiles in the box are on the side of the bricks (a side changes only
  // across stored voxels), or, without bricks, on the side of any one of them.
  const bool both = present > 0 && h.lo < level_ && h.hi >= level_;
  if (both) {
    add_side(h, sides_[0], gradient);
    add_side(h, sides_[1], gradient);
    return h;
  }
  Coord probe{};
  for (std::size_t a = 0; a < 3; ++a) probe[a] = std::max((*absent)[a] * kBrick, lo[a]);
  const double v = tiles_.value(probe);
  add_side(h, sides_[v < level_ ? 0 : 1], gradient);
  return h;
}

std::size_t SparseBspline::bytes() const {
  std::size_t tiles = 0;
  for (const auto& [shift, level] : tiles_.levels)
    tiles += level.size() * (sizeof(Coord) + sizeof(double) + 16);
  return coefficients_.size() * sizeof(float) + keys_.size() * (sizeof(Coord) + sizeof(Summary)) +
         index_.size() * (sizeof(Coord) + sizeof(std::uint32_t) + 16) + tiles;
}

}  // namespace isopatch::vdb
