#pragma once
// Points hashed into cubes of one side: every point within that distance of a query lies in the 27
// cubes around the query's own. For neighbourhood queries among scattered points (singular points to
// merge, balls to leave out, size sources), where a tree would be more than is needed.

#include <isopatch/geometry.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace isopatch {

class PointGrid {
 public:
  /// \pre size > 0 and finite.
  explicit PointGrid(double size) : size_(size) {}

  /// Adds point number `id` at p (ids are the caller's: indices into its own array).
  void insert(const Vec3& p, std::size_t id) { cells_[cell_of(p)].push_back(id); }

  /// Calls visit(id) for every point inserted in the 27 cubes around p's, cube by cube (z, y, x
  /// ascending) and within a cube in insertion order: the same order whatever else was inserted.
  template <typename Visit>
  void near(const Vec3& p, Visit&& visit) const {
    const Cell c = cell_of(p);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(Cell{c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells_.end()) continue;
          for (const std::size_t id : it->second) visit(id);
        }
  }

  double size() const { return size_; }

 private:
  using Cell = std::array<std::int64_t, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      std::uint64_t h = 1469598103934665603ULL;  // FNV-1a over the three coordinates
      for (const std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ULL;
      return static_cast<std::size_t>(h);
    }
  };
  Cell cell_of(const Vec3& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / size_)),
            static_cast<std::int64_t>(std::floor(p.y() / size_)),
            static_cast<std::int64_t>(std::floor(p.z() / size_))};
  }

  double size_;
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> cells_;
};

}  // namespace isopatch
