// PatchTemplate: picks the layout for n, derives side lists and coordinates from the tags, and caches
// one template per (n, r, kind).
#include "ngon/patch_template.hpp"

#include "ngon/template_layouts.hpp"

#include <isopatch/error.hpp>

#include <cassert>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <utility>

namespace isopatch {
namespace {

int checked_resolution(int r) {
  if (r < PatchTemplate::kMinResolution || r > PatchTemplate::kMaxResolution) {
    throw InputError("patch template: resolution " + std::to_string(r) + " is outside 1..64");
  }
  return r;
}

}  // namespace

PatchTemplate::PatchTemplate(int n, int r, CoordinateKind kind)
    : domain_(n), r_(checked_resolution(r)), kind_(kind) {
  TemplateLayout layout = n == 3   ? triangle_grid_layout(domain_, r)
                          : n == 4 ? quad_grid_layout(domain_, r)
                                   : ring_layout(domain_, r);
  points_ = std::move(layout.points);
  tags_ = std::move(layout.tags);
  triangles_ = std::move(layout.triangles);
  centre_ = layout.centre;

  const auto un = static_cast<std::size_t>(n);
  const auto ur = static_cast<std::size_t>(r);
  side_vertices_.assign(un * (ur + 1), -1);
  lambdas_.assign(un * points_.size(), 0.0);
  for (std::size_t v = 0; v < points_.size(); ++v) {
    const VertexTag& tag = tags_[v];
    const int vi = static_cast<int>(v);
    std::span<double> lambda(lambdas_.data() + v * un, un);
    switch (tag.kind) {
      case VertexTag::Kind::Corner: {
        const auto k = static_cast<std::size_t>(tag.side);
        side_vertices_[k * (ur + 1)] = vi;
        side_vertices_[static_cast<std::size_t>(domain_.wrap(tag.side - 1)) * (ur + 1) + ur] = vi;
        lambda[k] = 1.0;
        break;
      }
      case VertexTag::Kind::Side: {
        const auto k = static_cast<std::size_t>(tag.side);
        const double t = static_cast<double>(tag.index) / static_cast<double>(r);
        side_vertices_[k * (ur + 1) + static_cast<std::size_t>(tag.index)] = vi;
        lambda[k] = 1.0 - t;
        lambda[static_cast<std::size_t>(domain_.wrap(tag.side + 1))] = t;
        break;
      }
      case VertexTag::Kind::Interior:
        barycentric_coordinates(domain_, points_[v], kind_, lambda);
        break;
    }
  }
  for ([[maybe_unused]] int s : side_vertices_) assert(s >= 0);
}

std::span<const double> PatchTemplate::lambda(int v) const {
  const auto n = static_cast<std::size_t>(sides());
  return {lambdas_.data() + static_cast<std::size_t>(v) * n, n};
}

std::span<const int> PatchTemplate::side_vertices(int k) const {
  const auto count = static_cast<std::size_t>(r_ + 1);
  return {side_vertices_.data() + static_cast<std::size_t>(domain_.wrap(k)) * count, count};
}

std::shared_ptr<const PatchTemplate> patch_template(int n, int r, CoordinateKind kind) {
  using Key = std::tuple<int, int, CoordinateKind>;
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const PatchTemplate>> cache;
  const Key key{n, r, kind};
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
  }
  // Built outside the lock so that other sizes stay available meanwhile; bad (n, r) throws here, before
  // anything is stored. If two threads race, both build and the first one stored wins.
  auto built = std::make_shared<const PatchTemplate>(n, r, kind);
  const std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, std::move(built)).first->second;
}

}  // namespace isopatch
