// A partition of convex cells for the projection mesher (convex_partition.hpp).
#include "partition/convex_partition.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "partition/cell_checks.hpp"
#include "partition/cell_tests.hpp"
#include "partition/convex_cell_tests.hpp"
#include "partition/convex_overlay.hpp"
#include "partition/point_index.hpp"
#include "surface/bracketed_root.hpp"
#include "surface/sign_rule.hpp"

namespace isopatch {
namespace {

std::pair<std::uint32_t, std::uint32_t> segment_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

using SegmentPair = std::pair<std::uint32_t, std::uint32_t>;  // vertex ids, first < second

void check_cancel(const ConvexPartitionSettings& s) {
  if (s.cancel && s.cancel->load(std::memory_order_relaxed)) throw LimitError("cancelled");
}

/// f at every point of the index from `values.size()` on (in parallel, slot per point). A point whose
/// distance to f = 0 (to first order, |f| / |grad f|) is within `tolerance`, the distance under which
/// points are one, lies on the surface: its value is taken as 0 (positive by the sign rule, as an exact
/// zero). Where a cell's vertex lies on the surface (a region's corner the surface passes through, or
/// only touches), rounding no longer decides its sign, and every crossing next to it is that vertex.
void sample_new_points(const Sampler& f, const PointIndex& points, std::vector<double>& values,
                       double& largest, double tolerance) {
  const std::size_t first = values.size();
  values.resize(points.points().size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first, values.size(), 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) values[i] = f.value(points.points()[i]);
  });
  for (std::size_t i = first; i < values.size(); ++i) largest = std::max(largest, std::abs(values[i]));
  // Only values far below f's spread over the cells can be this close to f = 0 (|grad f| times a
  // cell's size is of the order of that spread, the tolerance 1e-9 of a cell's size or less).
  const double small = 1e-6 * largest;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(first, values.size(), 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      if (!(std::abs(values[i]) <= small) || values[i] == 0.0) continue;
      const ValueGradient vg = f.value_gradient_unchecked(points.points()[i]);
      if (std::abs(values[i]) <= tolerance * vg.gradient.norm()) values[i] = 0.0;
    }
  });
}

/// A vertex on the surface (value 0, see sample_new_points) makes a crossing, at itself, on every edge
/// to a neighbour of the other sign: it takes the sign that makes fewer of them (positive on a tie, as
/// 0 is), so that crossings at one point, and pieces of surface of no area, are rare. Where the surface
/// only touches the cells (a region's corner that f = 0 meets in that point alone) its neighbours share
/// a sign and no crossing is made; where it passes through a corner of three planes, one.
void zeros_take_the_sign_of_fewer_crossings(const std::vector<ConvexLeaf>& leaves,
                                            const std::vector<std::vector<std::uint32_t>>& leaf_vertices,
                                            std::vector<double>& values) {
  std::map<std::uint32_t, std::set<std::uint32_t>> neighbours;  // of each zero vertex
  for (std::size_t c = 0; c < leaves.size(); ++c)
    for (const ConvexCell::Face& face : leaves[c].cell.faces())
      for (std::size_t k = 0; k < face.vertices.size(); ++k) {
        const std::uint32_t a = leaf_vertices[c][face.vertices[k]];
        const std::uint32_t b = leaf_vertices[c][face.vertices[(k + 1) % face.vertices.size()]];
        if (values[a] == 0.0) neighbours[a].insert(b);
        if (values[b] == 0.0) neighbours[b].insert(a);
      }
  for (const auto& [z, around] : neighbours) {
    std::size_t positive = 0, negative = 0;
    for (std::uint32_t n : around) {
      positive += values[n] > 0.0 ? 1 : 0;
      negative += is_negative(values[n]) ? 1 : 0;
    }
    if (positive < negative) values[z] = -std::numeric_limits<double>::min();
  }
}

/// A piece's vertices as the cell sees them: counter-clockwise about the cell's outward normal.
std::vector<std::uint32_t> oriented(const OverlayPiece& piece, std::uint32_t cell) {
  std::vector<std::uint32_t> v = piece.vertices;
  if (piece.cells[0] != cell) std::reverse(v.begin(), v.end());
  return v;
}

/// One loop side inside one piece.
struct PieceSide {
  std::uint32_t from = 0, to = 0;  ///< crossing ids
  std::uint32_t piece = 0;
};

struct CellVerdict {
  std::vector<CellLoop> loops;
  ComplexReason reason = ComplexReason::None;
};

}  // namespace

CellPartition build_convex_partition(const Surface& surface, const Box& region,
                                     const std::vector<ConvexLeaf>& leaves,
                                     const ConvexPartitionSettings& settings,
                                     std::vector<std::size_t>* cell_leaves) {
  const Sampler f(surface);
  if (cell_leaves) cell_leaves->clear();
  CellPartition out;
  out.region = region;
  out.start_level = settings.start_level;
  if (leaves.empty()) return out;
  std::vector<double> sizes;
  sizes.reserve(leaves.size());
  for (const ConvexLeaf& leaf : leaves) sizes.push_back(leaf.cell.bounds().size().maxCoeff());
  std::vector<double> sorted = sizes;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double magnitude = std::max(region.lo.cwiseAbs().maxCoeff(), region.hi.cwiseAbs().maxCoeff());
  const double tolerance = std::max(1e-9 * *std::min_element(sizes.begin(), sizes.end()),
                                    1024.0 * std::numeric_limits<double>::epsilon() * magnitude);
  PointIndex points(region.lo, median, tolerance);
  double largest = 0.0;  // the largest |f| sampled so far
  // 1. Vertices of every leaf, their signs, and the leaves holding a sign change.
  std::vector<bool> wanted(leaves.size(), false);
  std::vector<std::vector<std::uint32_t>> leaf_vertices(leaves.size());
  for (std::size_t c = 0; c < leaves.size(); ++c)
    for (const Vec3& p : leaves[c].cell.vertices()) leaf_vertices[c].push_back(points.insert(p));
  std::vector<double> values;
  sample_new_points(f, points, values, largest, tolerance);
  zeros_take_the_sign_of_fewer_crossings(leaves, leaf_vertices, values);
  check_cancel(settings);
  for (std::size_t c = 0; c < leaves.size(); ++c) {
    bool neg = false, pos = false;
    for (std::uint32_t v : leaf_vertices[c]) (is_negative(values[v]) ? neg : pos) = true;
    wanted[c] = neg && pos;
  }
  // 2. Shared faces of those leaves, and f at the points the overlay added.
  std::vector<ConvexCell> cells;
  cells.reserve(leaves.size());
  for (const ConvexLeaf& leaf : leaves) cells.push_back(leaf.cell);
  // A neighbour whose own vertices share a sign may still see the surface through a shared piece (a
  // finer neighbour's vertex inside its face has the other sign): it holds the surface too. Grown
  // until no piece of a wanted cell with a sign change leads to an unwanted one.
  Overlay overlay;
  for (bool grown = true; grown;) {
    overlay = overlay_cells(cells, wanted, points, settings.strict);
    sample_new_points(f, points, values, largest, tolerance);
    check_cancel(settings);
    grown = false;
    for (std::size_t c = 0; c < leaves.size(); ++c)
      for (std::uint32_t piece : overlay.cell_pieces[c]) {
        const OverlayPiece& op = overlay.pieces[piece];
        const std::uint32_t other = op.cells[0] == c ? op.cells[1] : op.cells[0];
        if (other == kNoNeighbour || wanted[other]) continue;
        bool neg = false, pos = false;
        for (std::uint32_t v : op.vertices) (is_negative(values[v]) ? neg : pos) = true;
        if (neg && pos) wanted[other] = grown = true;
      }
  }
  const auto& P = points.points();
  // 3. Segments of the wanted cells: crossings where the end signs differ, the edge test on all.
  std::vector<SegmentPair> segments;
  for (std::size_t c = 0; c < leaves.size(); ++c)
    for (std::uint32_t piece : overlay.cell_pieces[c]) {
      const auto& v = overlay.pieces[piece].vertices;
      for (std::size_t k = 0; k < v.size(); ++k) segments.push_back(segment_key(v[k], v[(k + 1) % v.size()]));
    }
  std::sort(segments.begin(), segments.end());
  segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
  const auto segment_index = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = segment_key(a, b);
    return static_cast<std::size_t>(std::lower_bound(segments.begin(), segments.end(), key) -
                                    segments.begin());
  };
  std::vector<std::uint8_t> edge_ok(segments.size(), 1);
  std::vector<std::int64_t> crossing_of(segments.size(), -1);
  std::vector<std::size_t> crossed;
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (is_negative(values[segments[s].first]) != is_negative(values[segments[s].second])) {
      crossing_of[s] = static_cast<std::int64_t>(crossed.size());
      crossed.push_back(s);
    }
  out.corners.resize(crossed.size());
  std::vector<std::uint64_t> root_evaluations(crossed.size(), 0);
  std::vector<std::uint8_t> certified(segments.size(), 0);
  const int samples = settings.edge_samples;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segments.size(), 64), [&](const auto& range) {
    check_cancel(settings);
    for (std::size_t s = range.begin(); s != range.end(); ++s) {
      std::uint32_t a = segments[s].first, b = segments[s].second;
      const bool differ = crossing_of[s] >= 0;
      if (differ && !is_negative(values[a])) std::swap(a, b);  // a: the negative end
      int changes = 0;
      bool last = is_negative(values[a]);
      // f monotone along the segment: at most the one sign change its ends show, no samples needed.
      certified[s] = settings.use_intervals && segment_monotone_by_interval(surface, P[a], P[b]) ? 1 : 0;
      for (int k = 1; k <= samples && !certified[s]; ++k) {
        const bool now =
            is_negative(f.value(P[a] + (static_cast<double>(k) / (samples + 1)) * (P[b] - P[a])));
        changes += now != last ? 1 : 0;
        last = now;
      }
      changes += is_negative(values[b]) != last ? 1 : 0;
      edge_ok[s] = certified[s] || changes == (differ ? 1 : 0) ? 1 : 0;
      if (!differ) continue;
      const Vec3 A = P[a], d = P[b] - P[a];
      std::uint64_t count = 0;
      const double t = bracketed_root(
          [&](double u) {
            ++count;
            return f.value(A + u * d);
          },
          0.0, values[a], 1.0, values[b], kSegmentRootTolerance, kSegmentRootIterations);
      const auto i = static_cast<std::size_t>(crossing_of[s]);
      root_evaluations[i] = count;
      // An end on the surface is the crossing itself, to the bit.
      const Vec3 position = t == 1.0 ? P[b] : t == 0.0 ? A : A + t * d;
      out.corners[i] = CellCorner{position, d, f.value_gradient(position).gradient};
    }
  });
  // Gradients at the vertices of the wanted cells, for the face and normal-cone tests.
  std::vector<std::uint32_t> wanted_points;
  for (std::size_t c = 0; c < leaves.size(); ++c)
    for (std::uint32_t piece : overlay.cell_pieces[c])
      wanted_points.insert(wanted_points.end(), overlay.pieces[piece].vertices.begin(),
                           overlay.pieces[piece].vertices.end());
  std::sort(wanted_points.begin(), wanted_points.end());
  wanted_points.erase(std::unique(wanted_points.begin(), wanted_points.end()), wanted_points.end());
  std::vector<Vec3> gradients(P.size(), Vec3::Zero());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, wanted_points.size(), 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i)
      gradients[wanted_points[i]] = f.value_gradient_unchecked(P[wanted_points[i]]).gradient;
  });
  // 4. Per cell: the sides within each piece, chained into loops, and the verdict.
  const double cos_cone = std::cos(settings.cone_angle_deg * std::numbers::pi / 180.0);
  std::vector<CellVerdict> verdicts(leaves.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size(), 16), [&](const auto& range) {
    check_cancel(settings);
    for (std::size_t c = range.begin(); c != range.end(); ++c) {
      if (!wanted[c]) continue;
      CellVerdict& verdict = verdicts[c];
      std::vector<PieceSide> sides;
      bool ambiguous = false, edges = true, faces = true;
      std::vector<Vec3> cone;  // gradients at the cell's vertices and corners
      for (std::uint32_t piece : overlay.cell_pieces[c]) {
        const std::vector<std::uint32_t> v = oriented(overlay.pieces[piece], static_cast<std::uint32_t>(c));
        std::vector<std::pair<std::uint32_t, bool>> events;  // crossing, entering the negative part
        for (std::size_t k = 0; k < v.size(); ++k) {
          const std::uint32_t a = v[k], b = v[(k + 1) % v.size()];
          const std::size_t s = segment_index(a, b);
          edges = edges && edge_ok[s] != 0;
          if (crossing_of[s] < 0) continue;
          events.emplace_back(static_cast<std::uint32_t>(crossing_of[s]), is_negative(values[b]));
        }
        for (std::uint32_t id : v) cone.push_back(gradients[id]);
        if (events.empty()) continue;
        std::vector<Vec3> in_face;
        in_face.reserve(v.size());
        for (std::uint32_t id : v) in_face.push_back(gradients[id]);
        faces = faces && in_plane_gradients_agree(in_face, overlay.pieces[piece].normal);
        // Rotate to start at an entering crossing; crossings then alternate entering, leaving.
        const auto first = std::find_if(events.begin(), events.end(), [](const auto& e) { return e.second; });
        std::rotate(events.begin(), first, events.end());
        const std::size_t pairs = events.size() / 2;
        bool joined = false;  // whether the negative arcs are joined across the piece
        if (pairs > 1) {
          ambiguous = true;
          std::vector<std::uint32_t> ids = v;
          std::sort(ids.begin(), ids.end());
          Vec3 centre = Vec3::Zero();
          for (std::uint32_t id : ids) centre += P[id];
          joined = is_negative(f.value(centre / static_cast<double>(ids.size())));
        }
        for (std::size_t i = 0; i < pairs; ++i) {
          const std::size_t enter = joined ? 2 * ((i + 1) % pairs) : 2 * i;
          sides.push_back({events[enter].first, events[2 * i + 1].first, piece});
        }
      }
      // Chain: each crossing starts one side of this cell and ends another.
      std::map<std::uint32_t, std::size_t> starting;
      for (std::size_t i = 0; i < sides.size(); ++i)
        if (!starting.emplace(sides[i].from, i).second)
          throw Error(ErrorKind::Internal, "convex partition: a crossing starts two sides of one cell");
      std::vector<bool> used(sides.size(), false);
      for (std::size_t s0 = 0; s0 < sides.size(); ++s0) {
        if (used[s0]) continue;
        CellLoop loop;
        for (std::size_t s = s0; !used[s];) {
          used[s] = true;
          loop.corners.push_back(sides[s].from);
          loop.side_faces.push_back(sides[s].piece);
          const auto it = starting.find(sides[s].to);
          if (it == starting.end())
            throw Error(ErrorKind::Internal, "convex partition: an open loop in a cell");
          s = it->second;
        }
        verdict.loops.push_back(std::move(loop));
      }
      if (verdict.loops.size() > 1) {
        verdict.reason = ComplexReason::SeveralLoops;
      } else if (ambiguous) {
        verdict.reason = ComplexReason::AmbiguousFace;
      } else if (!edges) {
        verdict.reason = ComplexReason::EdgeTest;
      } else if (!verdict.loops.empty()) {
        const CellLoop& loop = verdict.loops.front();
        Vec3 mean = Vec3::Zero(), newell = Vec3::Zero();
        for (std::size_t k = 0; k < loop.corners.size(); ++k) {
          mean += out.corners[loop.corners[k]].gradient.normalized();
          cone.push_back(out.corners[loop.corners[k]].gradient);
          newell += out.corners[loop.corners[k]].position.cross(
              out.corners[loop.corners[(k + 1) % loop.corners.size()]].position);
        }
        if (!faces)
          verdict.reason = ComplexReason::FaceTest;
        else if (!gradients_within_cone(cone, cos_cone))
          verdict.reason = ComplexReason::NormalCone;
        else if (!(newell.dot(mean) > 0.0))
          verdict.reason = ComplexReason::Orientation;
      }
    }
  });
  // 5. The partition: cells in leaf order, faces in order of first use.
  std::vector<std::int64_t> face_of(overlay.pieces.size(), -1);
  for (std::size_t c = 0; c < leaves.size(); ++c) {
    if (!wanted[c]) continue;
    CellVerdict& verdict = verdicts[c];
    PartitionCell cell;
    cell.bounds = leaves[c].cell.bounds();
    cell.size = leaves[c].size;
    cell.level = leaves[c].level;
    cell.reason = verdict.reason;
    for (const ConvexCell::Face& face : leaves[c].cell.faces())
      cell.planes.push_back(leaves[c].cell.planes()[face.plane]);
    const auto index = static_cast<std::uint32_t>(out.cells.size());
    if (cell_leaves) cell_leaves->push_back(c);
    for (CellLoop& loop : verdict.loops) {
      for (std::uint32_t& piece : loop.side_faces) {
        if (face_of[piece] < 0) {
          face_of[piece] = static_cast<std::int64_t>(out.faces.size());
          const OverlayPiece& op = overlay.pieces[piece];
          CellFace face;
          face.normal = op.normal;
          face.axis = op.axis;
          face.region = Box{P[op.vertices.front()], P[op.vertices.front()]};
          for (std::uint32_t v : op.vertices) {
            face.region.lo = face.region.lo.cwiseMin(P[v]);
            face.region.hi = face.region.hi.cwiseMax(P[v]);
          }
          out.faces.push_back(face);
        }
        piece = static_cast<std::uint32_t>(face_of[piece]);
        auto& owners = out.faces[piece].cells;
        if (owners[0] != index && owners[1] != index) {
          if (owners[0] == kNoCell)
            owners[0] = index;
          else
            owners[1] = index;
          if (owners[1] != kNoCell && owners[1] < owners[0]) std::swap(owners[0], owners[1]);
        }
      }
      out.stats.loops += 1;
      out.stats.max_loop_size = std::max<std::uint64_t>(out.stats.max_loop_size, loop.corners.size());
    }
    cell.loops = std::move(verdict.loops);
    if (cell.reason == ComplexReason::None)
      ++out.stats.simple_leaves;
    else {
      ++out.stats.complex_leaves;
      ++out.stats.complex_by_reason[static_cast<std::size_t>(cell.reason)];
    }
    ++out.stats.leaves_per_depth[static_cast<std::size_t>(std::clamp(cell.level, 0, kMaxPartitionLevel))];
    out.cells.push_back(std::move(cell));
  }
  out.stats.cells_visited = leaves.size();
  for (std::uint8_t c : certified) out.stats.edges_certified_by_interval += c;
  for (std::uint64_t n : root_evaluations) out.stats.root_evaluations += n;
  out.stats.value_evaluations = f.value_count();
  out.stats.gradient_evaluations = f.gradient_count();
  return out;
}

}  // namespace isopatch
