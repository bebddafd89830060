// Convex cells by successive clipping (convex_cell.hpp).
#include "partition/convex_cell.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace isopatch {
namespace {

bool lexicographic_less(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

/// Two unit vectors perpendicular to n and to each other, (u, v, n) right-handed.
std::pair<Vec3, Vec3> plane_basis(const Vec3& n) {
  const Vec3 helper = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = n.cross(helper).normalized();
  return {u, n.cross(u)};
}

}  // namespace

CellPlane make_cell_plane(double a, double b, double c, double d, std::int64_t label) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d))
    throw InputError("convex cell: a plane has a coefficient that is not a finite number");
  const Vec3 n(a, b, c);
  const double length = n.stableNorm();
  if (!(length > 0.0)) throw InputError("convex cell: a plane has no normal (a = b = c = 0)");
  return CellPlane{n / length, d / length, label};
}

double cell_tolerance(double scale, double magnitude) {
  return std::max(1e-12 * scale, 64.0 * std::numeric_limits<double>::epsilon() * magnitude);
}

ConvexCell ConvexCell::box(const Box& b, double tolerance) {
  if (!b.valid()) throw InputError("convex cell: the box must be finite with lo < hi on every axis");
  ConvexCell cell;
  cell.tolerance_ = tolerance;
  for (int i = 0; i < 8; ++i)
    cell.vertices_.emplace_back((i & 1) ? b.hi.x() : b.lo.x(), (i & 2) ? b.hi.y() : b.lo.y(),
                                (i & 4) ? b.hi.z() : b.lo.z());
  // Per axis: the low face (normal -e) and the high face (normal +e), counter-clockwise from outside.
  static constexpr std::uint32_t kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                 {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const bool high = (f % 2) == 1;
    CellPlane plane;
    plane.normal = Vec3::Zero();
    plane.normal[axis] = high ? 1.0 : -1.0;
    plane.offset = high ? -b.hi[axis] : b.lo[axis];
    plane.label = -1 - f;
    cell.planes_.push_back(plane);
    cell.faces_.push_back(
        Face{static_cast<std::size_t>(f), {kFaces[f][0], kFaces[f][1], kFaces[f][2], kFaces[f][3]}});
  }
  return cell;
}

bool ConvexCell::clip(const CellPlane& plane) {
  if (empty()) return false;
  std::vector<double> dist(vertices_.size());
  bool any_out = false, any_in = false;
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    dist[i] = plane.distance(vertices_[i]);
    any_out = any_out || dist[i] > tolerance_;
    any_in = any_in || dist[i] < -tolerance_;
  }
  if (!any_out) return true;  // redundant within the tolerance
  if (!any_in) {
    faces_.clear();
    vertices_.clear();
    return false;
  }
  auto out = [&](std::uint32_t i) { return dist[i] > tolerance_; };
  auto on = [&](std::uint32_t i) { return std::abs(dist[i]) <= tolerance_; };
  std::vector<Vec3> points = vertices_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> cuts;
  // The crossing of edge (i, j), one inside and one beyond: interpolated from the lexicographically
  // smaller end, so two cells sharing the edge compute the same bits.
  auto cut = [&](std::uint32_t i, std::uint32_t j) {
    const auto key = std::minmax(i, j);
    if (const auto it = cuts.find(key); it != cuts.end()) return it->second;
    std::uint32_t a = i, b = j;
    if (lexicographic_less(vertices_[b], vertices_[a])) std::swap(a, b);
    const double t = dist[a] / (dist[a] - dist[b]);
    points.push_back(vertices_[a] + t * (vertices_[b] - vertices_[a]));
    const auto id = static_cast<std::uint32_t>(points.size() - 1);
    cuts.emplace(key, id);
    return id;
  };
  std::vector<Face> faces;
  std::vector<std::uint32_t> cap;
  for (const Face& face : faces_) {
    Face kept{face.plane, {}};
    const std::size_t n = face.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = face.vertices[k];
      const std::uint32_t j = face.vertices[(k + 1) % n];
      if (!out(i)) kept.vertices.push_back(i);
      if (on(i)) cap.push_back(i);
      if ((out(i) && dist[j] < -tolerance_) || (out(j) && dist[i] < -tolerance_)) {
        const std::uint32_t c = cut(i, j);
        kept.vertices.push_back(c);
        cap.push_back(c);
      }
    }
    if (kept.vertices.size() >= 3) faces.push_back(std::move(kept));
  }
  std::sort(cap.begin(), cap.end());
  cap.erase(std::unique(cap.begin(), cap.end()), cap.end());
  if (cap.size() >= 3) {
    // The cap is convex: its points ordered by angle about their mean are its boundary.
    Vec3 centre = Vec3::Zero();
    for (std::uint32_t i : cap) centre += points[i];
    centre /= static_cast<double>(cap.size());
    const auto [u, v] = plane_basis(plane.normal);
    std::vector<std::pair<double, std::uint32_t>> order;
    order.reserve(cap.size());
    for (std::uint32_t i : cap)
      order.emplace_back(std::atan2((points[i] - centre).dot(v), (points[i] - centre).dot(u)), i);
    std::sort(order.begin(), order.end());
    Face face{planes_.size(), {}};
    for (const auto& entry : order) face.vertices.push_back(entry.second);
    planes_.push_back(plane);
    faces.push_back(std::move(face));
  }
  // Keep only the vertices the faces use, merging those closer than the tolerance (nearly coincident
  // planes meet in nearly coincident points).
  std::vector<std::uint32_t> remap(points.size(), std::numeric_limits<std::uint32_t>::max());
  std::vector<Vec3> used;
  for (Face& face : faces) {
    std::vector<std::uint32_t> ids;
    for (std::uint32_t i : face.vertices) {
      if (remap[i] == std::numeric_limits<std::uint32_t>::max()) {
        std::uint32_t found = static_cast<std::uint32_t>(used.size());
        for (std::size_t k = 0; k < used.size(); ++k)
          if ((used[k] - points[i]).norm() <= tolerance_) {
            found = static_cast<std::uint32_t>(k);
            break;
          }
        if (found == used.size()) used.push_back(points[i]);
        remap[i] = found;
      }
      const std::uint32_t id = remap[i];
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    }
    while (ids.size() > 1 && ids.back() == ids.front()) ids.pop_back();
    face.vertices = std::move(ids);
  }
  std::erase_if(faces, [](const Face& f) { return f.vertices.size() < 3; });
  vertices_ = std::move(used);
  faces_ = std::move(faces);
  if (faces_.size() < 4 || !(volume() > 0.0)) {
    faces_.clear();
    vertices_.clear();
    return false;
  }
  return true;
}

double ConvexCell::volume() const {
  if (empty()) return 0.0;
  const Vec3 o = vertices_.front();
  double six_v = 0.0;
  for (const Face& f : faces_)
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k)
      six_v += (vertices_[f.vertices[0]] - o)
                   .dot((vertices_[f.vertices[k]] - o).cross(vertices_[f.vertices[k + 1]] - o));
  return six_v / 6.0;
}

Vec3 ConvexCell::centroid() const {
  if (empty()) return Vec3::Zero();
  const Vec3 o = vertices_.front();
  double total = 0.0;
  Vec3 sum = Vec3::Zero();
  for (const Face& f : faces_)
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k) {
      const Vec3& a = vertices_[f.vertices[0]];
      const Vec3& b = vertices_[f.vertices[k]];
      const Vec3& c = vertices_[f.vertices[k + 1]];
      const double v = (a - o).dot((b - o).cross(c - o));
      total += v;
      sum += v * (o + a + b + c) / 4.0;
    }
  return total > 0.0 ? Vec3(sum / total) : o;
}

Box ConvexCell::bounds() const {
  Box b{Vec3::Constant(std::numeric_limits<double>::infinity()),
        Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (const Vec3& p : vertices_) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

bool ConvexCell::contains(const Vec3& p, double margin) const {
  for (const Face& f : faces_)
    if (planes_[f.plane].distance(p) > margin) return false;
  return !empty();
}

ConvexCell intersect_half_spaces(const Box& bounds, const std::vector<CellPlane>& planes,
                                 double min_volume_fraction) {
  const double magnitude = std::max(bounds.lo.cwiseAbs().maxCoeff(), bounds.hi.cwiseAbs().maxCoeff());
  ConvexCell cell = ConvexCell::box(bounds, cell_tolerance(bounds.size().maxCoeff(), magnitude));
  const double box_volume = bounds.size().prod();
  for (std::size_t i = 0; i < planes.size(); ++i)
    if (!cell.clip(planes[i])) break;
  if (cell.empty() || !(cell.volume() > min_volume_fraction * box_volume))
    throw InputError("convex cell: the intersection of the " + std::to_string(planes.size()) +
                     " planes and the box is empty");
  return cell;
}

}  // namespace isopatch
