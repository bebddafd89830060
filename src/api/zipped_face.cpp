// One face of two smooth solids' intersection, trimmed and joined to the crease loops (zipped_face.hpp).
#include "api/zipped_face.hpp"

#include <isopatch/error.hpp>
#include <isopatch/remesh.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "api/band_join.hpp"
#include "api/box_boundary_loops.hpp"
#include "api/exact_positions.hpp"
#include "api/local_cleanup.hpp"
#include "csg/crease_graph.hpp"
#include "remesh/remesh_presets.hpp"

namespace isopatch {

namespace {

/// Vertices closer to o = 0 than this share of an edge (or beyond it) are trimmed: the band to the
/// crease is then at least that wide, and the clean-up evens it. Narrower bands are tried in turn where
/// the join fails (creases closer than the band is wide).
constexpr double kTrimWidths[] = {0.3, 0.15, 0.05};
/// A trimmed piece with no vertex farther than this many edges from o = 0 lies in a strip between creases
/// (a sheet's wall meeting the cutter): it is dropped, and the strip joined crease to crease.
constexpr double kStripWidth = 1.5;
/// The opening keeps what lies within this many rings of a vertex farther than kStripWidth edges.
constexpr int kOpeningRings = 2;
/// A crease loop no walk reached that is nowhere wider than this many edges (a sliver between a crease and
/// the box, or between two creases), with at most kMostThinLoopPoints points, is closed by zipping its
/// two halves.
constexpr double kThinLoop = 2.0;
constexpr std::size_t kMostThinLoopPoints = 400;
/// The clean-up reaches this many rings from the band of new triangles.
constexpr int kCleanedRings = 3;
/// A vertex of the mesh's boundary on the box this close to an arc's end (in edges) is left out of the
/// face's boundary there.
constexpr double kNearArcEnd = 0.5;

/// `triangles` without those at a vertex where two fans of them meet (a bow tie), until none is left.
std::vector<Triangle> without_pinches(std::vector<Triangle> kept) {
  for (std::vector<std::uint32_t> pinched = pinched_vertices(kept); !pinched.empty();
       pinched = pinched_vertices(kept)) {
    const std::unordered_set<std::uint32_t> drop(pinched.begin(), pinched.end());
    std::erase_if(kept, [&drop](const Triangle& t) {
      return drop.count(t[0]) || drop.count(t[1]) || drop.count(t[2]);
    });
  }
  return kept;
}

/// The triangles of `kept` within kOpeningRings rings (through `kept`) of a vertex farther than
/// kStripWidth edges from o = 0: the thin tails of a piece, and thin pieces, go (a morphological opening).
std::vector<Triangle> opened(const std::vector<Triangle>& kept, const std::vector<double>& distance,
                             double edge) {
  std::unordered_map<std::uint32_t, int> ring;
  for (const Triangle& t : kept)
    for (std::uint32_t v : t)
      if (distance[v] < -kStripWidth * edge) ring[v] = 0;
  for (int r = 1; r <= kOpeningRings; ++r) {
    std::vector<std::uint32_t> reached;
    for (const Triangle& t : kept) {
      bool near = false;
      for (std::uint32_t v : t) {
        const auto it = ring.find(v);
        near = near || (it != ring.end() && it->second == r - 1);
      }
      if (near)
        for (std::uint32_t v : t)
          if (!ring.count(v)) reached.push_back(v);
    }
    for (std::uint32_t v : reached) ring.emplace(v, r);
  }
  std::vector<Triangle> out;
  for (const Triangle& t : kept)
    if (ring.count(t[0]) && ring.count(t[1]) && ring.count(t[2])) out.push_back(t);
  return without_pinches(std::move(out));
}

/// `kept` (triangles of a mesh whose vertices lie at `distance` from o = 0) without its edge-connected
/// pieces that lie within kStripWidth edges of o = 0 throughout.
std::vector<Triangle> without_thin_pieces(const std::vector<Triangle>& kept,
                                          const std::vector<double>& distance, double edge) {
  std::unordered_map<std::uint32_t, std::uint32_t> parent;
  const auto find = [&parent](std::uint32_t v) {
    auto it = parent.try_emplace(v, v).first;
    while (it->second != v) {
      v = it->second;
      it = parent.find(v);
    }
    return v;
  };
  for (const Triangle& t : kept)
    for (std::size_t k = 1; k < 3; ++k) {
      const std::uint32_t a = find(t[0]), b = find(t[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::unordered_set<std::uint32_t> thick;
  for (const Triangle& t : kept)
    for (std::uint32_t v : t)
      if (distance[v] < -kStripWidth * edge) thick.insert(find(v));
  std::vector<Triangle> out;
  for (const Triangle& t : kept)
    if (thick.count(find(t[0]))) out.push_back(t);
  return out;
}

/// A point of s = 0 near `p` (Newton steps along grad s).
Vec3 onto_surface(const Surface& s, Vec3 p) {
  for (int it = 0; it < 30; ++it) {
    const ValueGradient g = s.value_gradient(p);
    const double n2 = g.gradient.squaredNorm();
    if (!(n2 > 0.0) || !std::isfinite(g.value)) break;
    const Vec3 step = g.value / n2 * g.gradient;
    p -= step;
    if (step.norm() < 1e-15 * (1.0 + p.norm())) break;
  }
  return p;
}

/// Whether the loop lies within two edges of its centroid (a face that small, closed by a fan).
bool small_loop(const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions, double edge) {
  Vec3 centre = Vec3::Zero();
  for (std::uint32_t v : loop) centre += positions[v];
  centre /= static_cast<double>(loop.size());
  return std::all_of(loop.begin(), loop.end(),
                     [&](std::uint32_t v) { return (positions[v] - centre).norm() <= 2.0 * edge; });
}

/// A loop no wider than kThinLoop edges (a sliver of the face between a crease and the box) as its two
/// halves between its two points farthest apart: the backward one first, both from the first of those
/// points to the second (band_join.hpp zip_between closes it); nullopt when it is wider.
std::optional<std::array<std::vector<std::uint32_t>, 2>> thin_loop_halves(
    const std::vector<std::uint32_t>& loop, const std::vector<Vec3>& positions, double edge) {
  const std::size_t n = loop.size();
  if (n < 4 || n > kMostThinLoopPoints) return std::nullopt;
  std::size_t a = 0, b = 0;
  double widest = -1.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const double d = (positions[loop[i]] - positions[loop[j]]).norm();
      if (d > widest) {
        widest = d;
        a = i;
        b = j;
      }
    }
  std::array<std::vector<std::uint32_t>, 2> halves;
  for (std::size_t k = a;; k = (k + n - 1) % n) {
    halves[0].push_back(loop[k]);
    if (k == b) break;
  }
  for (std::size_t k = a;; k = (k + 1) % n) {
    halves[1].push_back(loop[k]);
    if (k == b) break;
  }
  for (int h = 0; h < 2; ++h)
    for (std::uint32_t v : halves[static_cast<std::size_t>(h)]) {
      double nearest = std::numeric_limits<double>::infinity();
      for (std::uint32_t w : halves[static_cast<std::size_t>(1 - h)])
        nearest = std::min(nearest, (positions[v] - positions[w]).norm());
      if (nearest > kThinLoop * edge) return std::nullopt;
    }
  return halves;
}

}  // namespace

Mesh zip_face_to_creases(const Mesh& mesh, const Surface& s, const Surface& o,
                         const std::vector<CreaseLoop>& loops, bool reversed, double edge,
                         const Settings& settings, const Box& box, bool whole, BoxCut cut) {
  // The crease points first, every loop in this face's boundary direction.
  Mesh face;
  std::vector<std::vector<std::uint32_t>> crease;
  for (const CreaseLoop& loop : loops) {
    std::vector<std::uint32_t> ids;
    for (const Vec3& p : loop.points) {
      ids.push_back(static_cast<std::uint32_t>(face.positions.size()));
      face.positions.push_back(p);
    }
    if (reversed) std::reverse(ids.begin(), ids.end());
    crease.push_back(std::move(ids));
  }
  const std::vector<Vec3> crease_points(face.positions);
  const std::size_t held = crease_points.size();
  // The distance to o = 0 at every vertex, to first order.
  std::vector<ValueGradient> values(mesh.positions.size());
  o.value_gradients(mesh.positions, values);
  std::vector<double> distance(mesh.positions.size());
  for (std::size_t v = 0; v < distance.size(); ++v) {
    const double n = values[v].gradient.norm();
    if (!std::isfinite(values[v].value) || !std::isfinite(n))
      throw EvaluationError("the cutting surface is not finite at " + point_text(mesh.positions[v]));
    distance[v] = n > 0.0 ? values[v].value / n : values[v].value;
  }
  // Where the box cuts the part (the crease in arcs from the box to the box), the face's boundary loops
  // are the arcs and the mesh's own boundary inside o between them (box_boundary_loops.hpp), its vertices
  // copied after the crease's points; the trimmed face keeps those it reaches, and is joined to the rest.
  std::vector<std::vector<std::uint32_t>> closed_loops, box_loops;
  std::vector<std::uint8_t> left_out(mesh.positions.size(), 0);
  std::unordered_map<std::uint32_t, std::uint32_t> copy;
  std::vector<std::vector<Vec3>> arcs;
  std::vector<std::size_t> arc_loop;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    if (loops[k].closed) {
      closed_loops.push_back(crease[k]);
      continue;
    }
    arc_loop.push_back(k);
    arcs.emplace_back();
    for (std::uint32_t v : crease[k]) arcs.back().push_back(face.positions[v]);
  }
  if (cut != BoxCut::None) {
    std::vector<std::uint8_t> inside(mesh.positions.size(), 0);
    for (std::size_t v = 0; v < inside.size(); ++v) inside[v] = distance[v] < 0.0 ? 1 : 0;
    for (const std::vector<BoundaryPoint>& loop : box_boundary_loops(mesh, inside, arcs, edge)) {
      std::vector<std::uint32_t> ids;
      const std::size_t n = loop.size();
      const auto position = [&](const BoundaryPoint& p) -> const Vec3& {
        return p.arc >= 0 ? arcs[static_cast<std::size_t>(p.arc)][p.index] : mesh.positions[p.index];
      };
      for (std::size_t k = 0; k < n; ++k) {
        const BoundaryPoint& p = loop[k];
        if (p.arc >= 0) {
          ids.push_back(crease[arc_loop[static_cast<std::size_t>(p.arc)]][p.index]);
          continue;
        }
        // A vertex of the mesh's boundary beside an arc's end, closer to it than kNearArcEnd edges, is
        // left out (the boundary goes straight from the arc's end to the next vertex).
        const BoundaryPoint& before = loop[(k + n - 1) % n];
        const BoundaryPoint& after = loop[(k + 1) % n];
        if (n > 4 && ((before.arc >= 0 && (position(before) - position(p)).norm() < kNearArcEnd * edge) ||
                      (after.arc >= 0 && (position(after) - position(p)).norm() < kNearArcEnd * edge))) {
          left_out[p.index] = 1;
          continue;
        }
        const auto [it, added] = copy.emplace(p.index, static_cast<std::uint32_t>(face.positions.size()));
        if (added) face.positions.push_back(mesh.positions[p.index]);
        if (cut == BoxCut::Ring) left_out[p.index] = 1;
        ids.push_back(it->second);
      }
      box_loops.push_back(std::move(ids));
    }
  }
  std::vector<std::vector<std::uint32_t>> walked;  // the loops the crease walk joins
  const std::size_t joined_points = face.positions.size();
  // The mesh where o < 0, clear of the crease by a band, joined to it; a narrower band where that fails.
  std::optional<BandJoin> band;
  std::size_t kept_triangles = 0;
  std::string failure;
  for (int trial = 0; trial < 3 * static_cast<int>(std::size(kTrimWidths)) && !band; ++trial) {
    // At each width: thin tails and pieces dropped (their strips joined crease to crease), then only thin
    // pieces, then none (walked, where the strips branch).
    const double width = kTrimWidths[trial / 3];
    std::vector<std::uint8_t> keep(mesh.positions.size(), 0);
    for (std::size_t v = 0; v < keep.size(); ++v)
      keep[v] = distance[v] < -width * edge && !left_out[v] ? 1 : 0;
    std::vector<Triangle> kept;
    for (const Triangle& t : mesh.triangles)
      if (keep[t[0]] && keep[t[1]] && keep[t[2]]) kept.push_back(t);
    kept = without_pinches(std::move(kept));
    if (trial % 3 == 0) kept = opened(kept, distance, edge);
    if (trial % 3 == 1) kept = without_thin_pieces(kept, distance, edge);
    face.positions.resize(joined_points);
    face.triangles.clear();
    std::vector<std::int64_t> id(mesh.positions.size(), -1);
    for (const Triangle& t : kept) {
      Triangle f{};
      for (std::size_t k = 0; k < 3; ++k) {
        if (id[t[k]] < 0) {
          const auto it = copy.find(t[k]);
          if (it != copy.end()) {
            id[t[k]] = it->second;
          } else {
            id[t[k]] = static_cast<std::int64_t>(face.positions.size());
            face.positions.push_back(mesh.positions[t[k]]);
          }
        }
        f[k] = static_cast<std::uint32_t>(id[t[k]]);
      }
      face.triangles.push_back(f);
    }
    std::optional<BoxJoin> at_box = BoxJoin{{}, {}, triangle_boundary_loops(face.triangles)};
    if (!box_loops.empty())
      at_box = join_at_the_box(face.positions, box_loops, at_box->free_boundary, failure);
    if (!at_box) continue;
    walked = closed_loops;
    walked.insert(walked.end(), at_box->free_loops.begin(), at_box->free_loops.end());
    band = join_band({face.positions, walked, at_box->free_boundary, edge}, failure);
    if (!band) continue;
    band->triangles.insert(band->triangles.end(), at_box->triangles.begin(), at_box->triangles.end());
    // Crease loops no walk reached and no strip took: faces under an edge, closed by fans.
    for (std::size_t c = 0; c < walked.size() && band; ++c)
      if (band->untouched[c] && !small_loop(walked[c], face.positions, edge) &&
          !thin_loop_halves(walked[c], face.positions, edge)) {
        failure = "the face of max(a, b) has a crease with no face beside it near " +
                  point_text(face.positions[walked[c].front()]) + ": creases closer than an edge";
        band.reset();
      }
    if (band) kept_triangles = face.triangles.size();
  }
  if (!band) throw CreaseError(failure + "; a smaller edge length");
  for (const Vec3& p : band->extra) face.positions.push_back(onto_surface(s, p));
  face.triangles.insert(face.triangles.end(), band->triangles.begin(), band->triangles.end());
  for (std::size_t c = 0; c < walked.size(); ++c) {
    if (!band->untouched[c]) continue;
    if (!small_loop(walked[c], face.positions, edge)) {
      const auto halves = thin_loop_halves(walked[c], face.positions, edge);
      zip_between(face.positions, (*halves)[0], (*halves)[1], face.triangles);
      continue;
    }
    Vec3 centre = Vec3::Zero();
    for (std::uint32_t v : walked[c]) centre += face.positions[v];
    centre /= static_cast<double>(walked[c].size());
    const auto middle = static_cast<std::uint32_t>(face.positions.size());
    face.positions.push_back(onto_surface(s, centre));
    for (std::size_t k = 0; k < walked[c].size(); ++k)
      face.triangles.push_back({walked[c][k], walked[c][(k + 1) % walked[c].size()], middle});
  }
  // The clean-up on s near the band, the crease held: its vertices come back bit for bit.
  RemeshSettings r = preset_remesh_settings(settings, kDefaultRemeshIterations);
  r.sizes = target_sizes(settings, box);
  r.sizes.largest = edge;
  r.sizes.smallest = std::min(r.sizes.smallest, edge);
  std::vector<std::uint8_t> seed(face.positions.size(), 0);
  for (std::size_t t = kept_triangles; t < face.triangles.size(); ++t)
    for (std::uint32_t v : face.triangles[t]) seed[v] = 1;
  if (whole) {
    r.hold_cut = true;
    remesh_on_surface(face, s, r);
  } else {
    clean_up_near(face, s, seed, kCleanedRings, r);
  }
  // Referenced vertices only, the crease's first (found by their positions), the others in triangle order.
  ExactPositionMap<std::uint32_t> crease_id;
  for (std::uint32_t k = 0; k < held; ++k) crease_id.emplace(crease_points[k], k);
  std::vector<Vec3> positions(crease_points);
  std::vector<std::int64_t> renumber(face.positions.size(), -1);
  for (Triangle& t : face.triangles)
    for (std::uint32_t& v : t) {
      if (renumber[v] < 0) {
        const auto it = crease_id.find(face.positions[v]);
        if (it != crease_id.end()) {
          renumber[v] = it->second;
        } else {
          renumber[v] = static_cast<std::int64_t>(positions.size());
          positions.push_back(face.positions[v]);
        }
      }
      v = static_cast<std::uint32_t>(renumber[v]);
    }
  face.positions = std::move(positions);
  face.attributes.clear();
  return face;
}

}  // namespace isopatch
