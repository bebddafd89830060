// Shared faces of convex cells (convex_overlay.hpp).
#include "partition/convex_overlay.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

namespace isopatch {
namespace {

std::pair<std::uint32_t, std::uint32_t> ordered_pair(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

/// A face of a cell as points, counter-clockwise about its outward normal.
std::vector<Vec3> face_points(const ConvexCell& cell, const ConvexCell::Face& face) {
  std::vector<Vec3> p;
  for (std::uint32_t v : face.vertices) p.push_back(cell.vertices()[v]);
  return p;
}

double polygon_area(const std::vector<Vec3>& p, const Vec3& normal) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t k = 0; k < p.size(); ++k) sum += p[k].cross(p[(k + 1) % p.size()]);
  return 0.5 * sum.dot(normal);
}

/// The part of polygon p with m . x + o <= 0 (points within tol of the line count as on it).
std::vector<Vec3> clip_polygon(const std::vector<Vec3>& p, const Vec3& m, double o, double tol) {
  std::vector<Vec3> out;
  const std::size_t n = p.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = p[k];
    const Vec3& b = p[(k + 1) % n];
    const double da = m.dot(a) + o, db = m.dot(b) + o;
    if (da <= tol) out.push_back(a);
    if ((da > tol && db < -tol) || (da < -tol && db > tol)) out.push_back(a + (da / (da - db)) * (b - a));
  }
  return out;
}

/// Polygon g clipped to the (convex) polygon f, both in one plane, f counter-clockwise about n.
std::vector<Vec3> intersect_polygons(const std::vector<Vec3>& f, std::vector<Vec3> g, const Vec3& n,
                                     double tol) {
  for (std::size_t k = 0; k < f.size() && g.size() >= 3; ++k) {
    const Vec3& a = f[k];
    const Vec3& b = f[(k + 1) % f.size()];
    const Vec3 edge = b - a;
    if (!(edge.norm() > 0.0)) continue;
    const Vec3 m = edge.cross(n).normalized();  // outward in the plane
    g = clip_polygon(g, m, -m.dot(a), tol);
  }
  return g;
}

int exact_axis(const Vec3& n) {
  for (int a = 0; a < 3; ++a)
    if (n[(a + 1) % 3] == 0.0 && n[(a + 2) % 3] == 0.0) return a;
  return -1;
}

/// Cells by the cells of a coarse grid their bounds overlap: candidates for neighbours.
class CellGrid {
 public:
  CellGrid(const std::vector<ConvexCell>& cells, double tol) : tol_(tol) {
    std::vector<double> sizes;
    origin_ = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (const ConvexCell& c : cells) {
      const Box b = c.bounds();
      sizes.push_back(b.size().maxCoeff());
      origin_ = origin_.cwiseMin(b.lo);
      bounds_.push_back(b);
    }
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2),
                     sizes.end());
    spacing_ = sizes.empty() ? 1.0 : sizes[sizes.size() / 2];
    for (std::uint32_t c = 0; c < cells.size(); ++c)
      visit(bounds_[c], [&](std::uint64_t key) { grid_[key].push_back(c); });
  }
  std::vector<std::uint32_t> near(const Box& b) const {
    std::vector<std::uint32_t> found;
    visit(b, [&](std::uint64_t key) {
      if (const auto it = grid_.find(key); it != grid_.end())
        found.insert(found.end(), it->second.begin(), it->second.end());
    });
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    std::erase_if(found, [&](std::uint32_t c) {
      const Box& o = bounds_[c];
      return ((o.lo.array() > b.hi.array() + tol_) || (o.hi.array() < b.lo.array() - tol_)).any();
    });
    return found;
  }

 private:
  template <class Visit>
  void visit(const Box& b, Visit&& fn) const {
    std::array<std::int64_t, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      lo[static_cast<std::size_t>(a)] =
          static_cast<std::int64_t>(std::floor((b.lo[a] - tol_ - origin_[a]) / spacing_));
      hi[static_cast<std::size_t>(a)] =
          static_cast<std::int64_t>(std::floor((b.hi[a] + tol_ - origin_[a]) / spacing_));
    }
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
          fn((static_cast<std::uint64_t>(i & 0x1fffff) << 42) |
             (static_cast<std::uint64_t>(j & 0x1fffff) << 21) | static_cast<std::uint64_t>(k & 0x1fffff));
  }
  double tol_;
  Vec3 origin_;
  double spacing_ = 1.0;
  std::vector<Box> bounds_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid_;
};

std::vector<std::uint32_t> to_ids(const std::vector<Vec3>& polygon, PointIndex& points) {
  std::vector<std::uint32_t> ids;
  for (const Vec3& p : polygon) {
    const std::uint32_t id = points.insert(p);
    if (ids.empty() || ids.back() != id) ids.push_back(id);
  }
  while (ids.size() > 1 && ids.back() == ids.front()) ids.pop_back();
  return ids;
}

}  // namespace

std::vector<std::uint32_t> with_edge_points(const std::vector<std::uint32_t>& polygon,
                                            const PointIndex& points) {
  std::vector<std::uint32_t> out;
  const auto& p = points.points();
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const std::uint32_t u = polygon[k];
    const std::uint32_t v = polygon[(k + 1) % polygon.size()];
    out.push_back(u);
    const Vec3 d = p[v] - p[u];
    const double length2 = d.squaredNorm();
    std::vector<std::pair<double, std::uint32_t>> inner;
    for (std::uint32_t w : points.near_segment(p[u], p[v], points.tolerance())) {
      if (w == u || w == v) continue;
      const double t = (p[w] - p[u]).dot(d) / length2;
      const double margin = points.tolerance() / std::sqrt(length2);
      if (t > margin && t < 1.0 - margin) inner.emplace_back(t, w);
    }
    std::sort(inner.begin(), inner.end());
    for (const auto& [t, w] : inner) out.push_back(w);
  }
  return out;
}

Overlay overlay_cells(const std::vector<ConvexCell>& cells, const std::vector<bool>& wanted,
                      PointIndex& points, bool strict) {
  const double tol = points.tolerance();
  const CellGrid grid(cells, tol);
  Overlay overlay;
  overlay.cell_pieces.assign(cells.size(), {});
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> shared;  // cell pair -> piece
  for (std::uint32_t c = 0; c < cells.size(); ++c) {
    if (!wanted[c]) continue;
    const ConvexCell& cell = cells[c];
    for (std::size_t fi = 0; fi < cell.faces().size(); ++fi) {
      const ConvexCell::Face& face = cell.faces()[fi];
      const CellPlane& plane = cell.planes()[face.plane];
      const std::vector<Vec3> fp = face_points(cell, face);
      const double area = polygon_area(fp, plane.normal);
      Box fb{fp.front(), fp.front()};
      for (const Vec3& q : fp) {
        fb.lo = fb.lo.cwiseMin(q);
        fb.hi = fb.hi.cwiseMax(q);
      }
      double covered = 0.0;
      std::vector<std::uint32_t> mine;
      for (std::uint32_t d : grid.near(fb)) {
        if (d == c) continue;
        const ConvexCell& other = cells[d];
        for (const ConvexCell::Face& g : other.faces()) {
          const CellPlane& gp = other.planes()[g.plane];
          if (gp.normal.dot(plane.normal) > -1.0 + 1e-9) continue;
          std::vector<Vec3> gpts = face_points(other, g);
          bool coplanar = true;
          for (const Vec3& q : gpts) coplanar = coplanar && std::abs(plane.distance(q)) <= 4.0 * tol;
          if (!coplanar) continue;
          const auto key = ordered_pair(c, d);
          if (const auto it = shared.find(key); it != shared.end()) {
            std::vector<Vec3> q;
            for (std::uint32_t v : overlay.pieces[it->second].vertices) q.push_back(points.points()[v]);
            covered += std::abs(polygon_area(q, overlay.pieces[it->second].normal));
            mine.push_back(it->second);
            continue;
          }
          // Computed once per pair, from the face of the lower cell: both cells see the same piece.
          std::vector<Vec3> lower = c < d ? fp : gpts;
          std::vector<Vec3> upper = c < d ? gpts : fp;
          const Vec3 n = c < d ? plane.normal : gp.normal;
          std::reverse(upper.begin(), upper.end());  // counter-clockwise about n
          const std::vector<Vec3> piece = intersect_polygons(lower, upper, n, tol);
          if (piece.size() < 3) continue;
          const double piece_area = polygon_area(piece, n);
          if (!(piece_area > 1e-9 * area)) continue;
          OverlayPiece op;
          op.cells = {key.first, key.second};
          op.normal = n;
          op.axis = exact_axis(n);
          op.vertices = to_ids(piece, points);
          if (op.vertices.size() < 3) continue;
          covered += piece_area;
          shared.emplace(key, static_cast<std::uint32_t>(overlay.pieces.size()));
          mine.push_back(static_cast<std::uint32_t>(overlay.pieces.size()));
          overlay.pieces.push_back(std::move(op));
        }
      }
      const double uncovered = (area - covered) / area;
      if (mine.empty()) {
        OverlayPiece op;
        op.cells = {c, kNoNeighbour};
        op.normal = plane.normal;
        op.axis = exact_axis(plane.normal);
        op.vertices = to_ids(fp, points);
        mine.push_back(static_cast<std::uint32_t>(overlay.pieces.size()));
        overlay.pieces.push_back(std::move(op));
      } else if (std::abs(uncovered) > 1e-6) {
        const std::string where = "cell " + std::to_string(c) + ", face " + std::to_string(fi);
        const std::string what = uncovered > 0.0 ? "the cells leave a gap (or do not meet face to face) at "
                                                 : "the cells overlap at ";
        if (strict) throw InputError("convex partition: " + what + where);
        throw Error(ErrorKind::Internal, "convex partition: " + what + where);
      }
      for (std::uint32_t piece : mine) overlay.cell_pieces[c].push_back(piece);
    }
  }
  for (OverlayPiece& piece : overlay.pieces) piece.vertices = with_edge_points(piece.vertices, points);
  return overlay;
}

}  // namespace isopatch
