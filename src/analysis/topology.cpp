// Topology of a triangle mesh from one sorted array of half-edges plus three union-find structures
// (vertices -> components, triangle corners -> vertex fans, boundary vertices -> boundary loops).
// Sorting 3F half-edges by their undirected key groups each edge's triangles together, which gives
// boundary, non-manifold and orientation checks in one pass, in O(F log F) time and O(V + F) memory.
#include <isopatch/error.hpp>
#include <isopatch/topology.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <numeric>
#include <string>

#include "analysis/mesh_neighbourhood.hpp"

namespace isopatch {
namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  /// Joins the sets of a and b; false when they already were one set.
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
  }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> size_;
};

struct HalfEdge {
  std::uint64_t key;          // (smaller vertex << 32) | larger vertex
  std::uint32_t corner_low;   // corner (3 * triangle + slot) of the smaller vertex
  std::uint32_t corner_high;  // corner of the larger vertex

  /// The triangle runs from the smaller to the larger vertex (both corners are of one triangle).
  bool forward() const { return (corner_low % 3 + 1) % 3 == corner_high % 3; }
};

void check_input(const Mesh& mesh) {
  const std::size_t n = mesh.positions.size();
  if (n > std::numeric_limits<std::uint32_t>::max() ||
      mesh.triangles.size() * 3 > std::numeric_limits<std::uint32_t>::max())
    throw InputError("analyze_topology: mesh too large for 32-bit indices");
  analysis::check_mesh(mesh, "analyze_topology");
}

bool zero_area(const Mesh& mesh, const Triangle& t) {
  const Vec3& a = mesh.positions[t[0]];
  const Vec3& b = mesh.positions[t[1]];
  const Vec3& c = mesh.positions[t[2]];
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return (b - a).cross(c - a).norm() <= 1e-12 * longest;
}

std::size_t count_duplicates(const std::vector<Vec3>& positions) {
  std::vector<std::uint32_t> order(positions.size());
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  auto less = [&](std::uint32_t i, std::uint32_t j) {
    const Vec3& p = positions[i];
    const Vec3& q = positions[j];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    return p.z() < q.z();
  };
  std::sort(order.begin(), order.end(), less);
  std::size_t duplicates = 0;
  for (std::size_t i = 1; i < order.size(); ++i)
    if (positions[order[i]] == positions[order[i - 1]]) ++duplicates;
  return duplicates;
}

std::optional<int> genus_of(const ComponentTopology& c) {
  if (c.non_manifold_edges != 0 || c.non_manifold_vertices != 0 || c.inconsistent_edges != 0)
    return std::nullopt;
  const long twice_genus = 2 - c.euler_characteristic - static_cast<long>(c.boundary_loops);
  if (twice_genus < 0 || twice_genus % 2 != 0) return std::nullopt;
  return static_cast<int>(twice_genus / 2);
}

/// Closed components beyond which nesting is not tested (each test costs a pass over the triangles).
constexpr std::ptrdiff_t kMaxNestingTests = 64;

/// Solid angle of triangle (a, b, c) seen from the origin, over 4 pi (Van Oosterom & Strackee 1983):
/// summed over a closed mesh, the winding number of the origin.
double winding_share(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return std::atan2(numerator, denominator) / (2.0 * std::numbers::pi);
}

/// Sets `outward` on every closed component: the winding number of the other closed components about
/// one of its vertices is 0 (an outer wall) and its volume positive, or 1 (the wall of a cavity) and its
/// volume negative. With more than kMaxNestingTests closed components (marching cubes of noise) only
/// the sign of the volume is looked at.
void mark_outward_components(const Mesh& mesh, const std::vector<std::uint32_t>& kept,
                             const std::vector<std::uint32_t>& component,
                             std::vector<ComponentTopology>& components) {
  const auto closed = std::count_if(components.begin(), components.end(),
                                    [](const ComponentTopology& c) { return c.closed(); });
  for (std::uint32_t index = 0; index < components.size(); ++index) {
    ComponentTopology& c = components[index];
    if (!c.closed()) continue;
    if (closed > kMaxNestingTests || closed == 1) {
      c.outward = c.volume > 0.0;
      continue;
    }
    // A vertex of this component; every other closed component's triangles wind around it.
    Vec3 p = Vec3::Zero();
    for (std::uint32_t t : kept)
      if (component[mesh.triangles[t][0]] == index) {
        p = mesh.positions[mesh.triangles[t][0]];
        break;
      }
    double winding = 0.0;
    for (std::uint32_t t : kept) {
      const std::uint32_t other = component[mesh.triangles[t][0]];
      if (other == index || !components[other].closed()) continue;
      const Triangle& tri = mesh.triangles[t];
      winding +=
          winding_share(mesh.positions[tri[0]] - p, mesh.positions[tri[1]] - p, mesh.positions[tri[2]] - p);
    }
    // Winding 0: an outer wall, outward with a positive volume; 1: a cavity wall, with a negative one;
    // anything else (overlapping or inverted walls): not outward.
    const long nesting = std::lround(winding);
    c.outward = nesting == 0 ? c.volume > 0.0 : nesting == 1 && c.volume < 0.0;
  }
}

}  // namespace

bool TopologyReport::outward_oriented() const {
  if (!consistently_oriented()) return false;
  return std::all_of(components.begin(), components.end(),
                     [](const ComponentTopology& c) { return !c.closed() || c.outward; });
}

TopologyReport analyze_topology(const Mesh& mesh) {
  check_input(mesh);
  const std::size_t n = mesh.positions.size();
  const std::vector<Triangle>& triangles = mesh.triangles;
  TopologyReport report;
  report.vertices = n;
  report.triangles = triangles.size();

  // Triangles that repeat an index have no well-defined edges: they are counted and set aside.
  std::vector<bool> referenced(n, false);
  std::vector<std::uint32_t> kept;
  kept.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::uint32_t i : triangles[t]) referenced[i] = true;
    if (analysis::repeats_vertex(triangles[t])) {
      ++report.degenerate_triangles;
      continue;
    }
    if (zero_area(mesh, triangles[t])) ++report.degenerate_triangles;
    kept.push_back(static_cast<std::uint32_t>(t));
  }
  report.unreferenced_vertices =
      static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
  report.duplicate_vertices = count_duplicates(mesh.positions);

  // Components: vertices joined by the triangles.
  UnionFind vertex_sets(n);
  for (std::uint32_t t : kept) {
    vertex_sets.unite(triangles[t][0], triangles[t][1]);
    vertex_sets.unite(triangles[t][1], triangles[t][2]);
  }
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> component_of_root(n, kNone);
  std::vector<std::uint32_t> component(n, kNone);
  for (std::uint32_t t : kept)
    for (std::uint32_t v : triangles[t]) {
      const std::uint32_t root = vertex_sets.find(v);
      if (component_of_root[root] == kNone) {
        component_of_root[root] = static_cast<std::uint32_t>(report.components.size());
        report.components.emplace_back();
      }
      if (component[v] == kNone) {
        component[v] = component_of_root[root];
        ++report.components[component[v]].vertices;
      }
    }

  // Volumes about the bounding-box centre, which keeps the rounding of the triple products small.
  const Box box = bounding_box(mesh);
  const Vec3 origin = n > 0 ? box.centre() : Vec3::Zero();
  for (std::uint32_t t : kept) {
    const Triangle& tri = triangles[t];
    ComponentTopology& c = report.components[component[tri[0]]];
    ++c.triangles;
    const Vec3 a = mesh.positions[tri[0]] - origin;
    const Vec3 b = mesh.positions[tri[1]] - origin;
    const Vec3 d = mesh.positions[tri[2]] - origin;
    c.volume += a.dot(b.cross(d)) / 6.0;
  }

  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * kept.size());
  for (std::uint32_t t : kept)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[t][k];
      const std::uint32_t b = triangles[t][(k + 1) % 3];
      const std::uint32_t ca = 3 * t + k;
      const std::uint32_t cb = 3 * t + (k + 1) % 3;
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      half_edges.push_back(a < b ? HalfEdge{key, ca, cb} : HalfEdge{key, cb, ca});
    }
  std::sort(half_edges.begin(), half_edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.corner_low < y.corner_low;
  });

  // Fans: the corners of a vertex are joined across every edge they share; each successful join
  // removes one fan from the count of that vertex.
  UnionFind corner_sets(3 * triangles.size());
  std::vector<std::uint32_t> fans(n, 0);
  for (std::uint32_t t : kept)
    for (std::uint32_t v : triangles[t]) ++fans[v];
  UnionFind boundary_sets(n);
  std::vector<bool> on_boundary(n, false);

  for (std::size_t begin = 0; begin < half_edges.size();) {
    std::size_t end = begin + 1;
    while (end < half_edges.size() && half_edges[end].key == half_edges[begin].key) ++end;
    const std::size_t count = end - begin;
    const auto low = static_cast<std::uint32_t>(half_edges[begin].key >> 32);
    const auto high = static_cast<std::uint32_t>(half_edges[begin].key & 0xffffffffu);
    ComponentTopology& c = report.components[component[low]];
    ++c.edges;
    if (count == 1) {
      ++c.boundary_edges;
      boundary_sets.unite(low, high);
      on_boundary[low] = on_boundary[high] = true;
    } else if (count > 2) {
      ++c.non_manifold_edges;
    } else if (half_edges[begin].forward() == half_edges[begin + 1].forward()) {
      ++c.inconsistent_edges;
    }
    for (std::size_t i = begin + 1; i < end; ++i) {
      if (corner_sets.unite(half_edges[begin].corner_low, half_edges[i].corner_low)) --fans[low];
      if (corner_sets.unite(half_edges[begin].corner_high, half_edges[i].corner_high)) --fans[high];
    }
    begin = end;
  }

  for (std::uint32_t v = 0; v < n; ++v) {
    if (component[v] == kNone) continue;
    ComponentTopology& c = report.components[component[v]];
    if (fans[v] > 1) ++c.non_manifold_vertices;
    if (on_boundary[v] && boundary_sets.find(v) == v) ++c.boundary_loops;
  }

  mark_outward_components(mesh, kept, component, report.components);

  for (ComponentTopology& c : report.components) {
    c.euler_characteristic =
        static_cast<long>(c.vertices) - static_cast<long>(c.edges) + static_cast<long>(c.triangles);
    c.genus = genus_of(c);
    report.edges += c.edges;
    report.boundary_edges += c.boundary_edges;
    report.non_manifold_edges += c.non_manifold_edges;
    report.non_manifold_vertices += c.non_manifold_vertices;
    report.inconsistent_edges += c.inconsistent_edges;
    report.euler_characteristic += c.euler_characteristic;
    if (c.closed() && c.genus) report.genus += *c.genus;
  }
  return report;
}

}  // namespace isopatch
