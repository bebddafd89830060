// Tangential moves towards a cotangent Laplacian exact for quadratics, see laplacian_exactness.hpp.
#include "remesh/laplacian_exactness.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numbers>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/triangle_angle.hpp"

namespace isopatch {
namespace {

/// A vertex's tangent frame.
struct TangentFrame {
  Vec3 e1, e2;
  explicit TangentFrame(const Vec3& normal) : e1(normal.unitOrthogonal()), e2(normal.cross(e1)) {}
  TangentFrame() = default;
};

/// A frame kept in single precision for the sweeps' per-vertex cache: any orthonormal pair serves as a
/// tangent frame, and the rounding only tilts it by 1e-7 (the same frame at every use within a sweep).
struct CompactTangentFrame {
  std::array<float, 3> e1{}, e2{};
  CompactTangentFrame() = default;
  explicit CompactTangentFrame(const TangentFrame& f) {
    for (int c = 0; c < 3; ++c) {
      e1[static_cast<std::size_t>(c)] = static_cast<float>(f.e1[c]);
      e2[static_cast<std::size_t>(c)] = static_cast<float>(f.e2[c]);
    }
  }
  TangentFrame widen() const {
    TangentFrame f;
    f.e1 = Vec3(static_cast<double>(e1[0]), static_cast<double>(e1[1]), static_cast<double>(e1[2]));
    f.e2 = Vec3(static_cast<double>(e2[0]), static_cast<double>(e2[1]), static_cast<double>(e2[2]));
    return f;
  }
};

/// What one triangle adds at one corner: the cotangent-weighted second moment of the corner's two
/// edges in the corner's tangent frame (m11, m12, m22) and the corner's mixed Voronoi area.
struct MomentSums {
  double m11 = 0.0, m12 = 0.0, m22 = 0.0, area = 0.0;
  MomentSums& operator+=(const MomentSums& o) {
    m11 += o.m11, m12 += o.m12, m22 += o.m22, area += o.area;
    return *this;
  }
  MomentSums& operator-=(const MomentSums& o) {
    m11 -= o.m11, m12 -= o.m12, m22 -= o.m22, area -= o.area;
    return *this;
  }
};

/// Pointers to the three frames of a triangle's corners, as triangle_sums takes them.
std::array<const TangentFrame*, 3> corner_frames(const std::array<TangentFrame, 3>& frames) {
  return {frames.data(), frames.data() + 1, frames.data() + 2};
}

/// The sums of triangle (x0, x1, x2) at each of its corners, corner k in frame *frames[k] (null: that
/// corner is not needed). False for a degenerate triangle. The mixed area follows Meyer et al. (2003)
/// exactly as the curvature analysis computes it.
bool triangle_sums(const std::array<const Vec3*, 3>& x, const std::array<const TangentFrame*, 3>& frames,
                   std::array<MomentSums, 3>& out) {
  // Plain arithmetic on doubles: this is the inner loop of the sweeps (and Eigen expressions are not
  // inlined in the sanitizer builds at -O1).
  double edge[3][3];  // edge[k] is opposite corner k: from corner k+1 to corner k+2
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) edge[k][c] = (*x[(k + 2) % 3])[c] - (*x[(k + 1) % 3])[c];
  const auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const double* u = edge[2];  // corner 0 -> corner 1
  const double* w = edge[1];  // corner 2 -> corner 0
  const double cross[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const double twice_area = std::sqrt(dot(cross, cross));
  if (!(twice_area > 0.0)) return false;
  double cot[3], length2[3];
  for (int k = 0; k < 3; ++k) {
    cot[k] = -dot(edge[(k + 1) % 3], edge[(k + 2) % 3]) / twice_area;
    length2[k] = dot(edge[k], edge[k]);
  }
  const int obtuse = cot[0] < 0.0 ? 0 : cot[1] < 0.0 ? 1 : cot[2] < 0.0 ? 2 : -1;
  for (int k = 0; k < 3; ++k) {
    const TangentFrame* f = frames[static_cast<std::size_t>(k)];
    if (!f) continue;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    // The corner's edges: to corner i is edge[j], to corner j is -edge[i] (the sign drops out of the
    // second moments).
    const double ai = dot(edge[j], f->e1.data()), bi = dot(edge[j], f->e2.data());
    const double aj = dot(edge[i], f->e1.data()), bj = dot(edge[i], f->e2.data());
    MomentSums& s = out[static_cast<std::size_t>(k)];
    s.m11 = cot[j] * ai * ai + cot[i] * aj * aj;
    s.m12 = cot[j] * ai * bi + cot[i] * aj * bj;
    s.m22 = cot[j] * bi * bi + cot[i] * bj * bj;
    s.area = obtuse < 0 ? (length2[j] * cot[j] + length2[i] * cot[i]) / 8.0
                        : twice_area / (obtuse == k ? 4.0 : 8.0);
  }
  return true;
}

/// The residual of summed moments (see the header); large when the area is not positive.
Eigen::Vector3d residual_of(const MomentSums& s) {
  if (!(s.area > 0.0)) return Eigen::Vector3d::Constant(1e3);
  const double scale = 1.0 / (4.0 * s.area);
  return {s.m11 * scale - 1.0, s.m22 * scale - 1.0, std::sqrt(2.0) * s.m12 * scale};
}

/// Position of vertex w when `moved` sits at p.
const Vec3& position(const EditableMesh& mesh, std::uint32_t w, std::uint32_t moved, const Vec3& p) {
  return w == moved ? p : mesh.positions[w];
}

/// Moment sums of v over its triangles in `frame`, `moved` at p; false when one is degenerate.
bool vertex_sums(const EditableMesh& mesh, std::uint32_t v, const TangentFrame& frame, std::uint32_t moved,
                 const Vec3& p, MomentSums& sums) {
  sums = {};
  std::array<MomentSums, 3> corners;
  for (std::uint32_t t : mesh.incident[v]) {
    const Triangle& tri = mesh.triangles[t];
    std::array<const TangentFrame*, 3> frames{nullptr, nullptr, nullptr};
    const std::size_t k = corner_index(tri, v);
    frames[k] = &frame;
    if (!triangle_sums({&position(mesh, tri[0], moved, p), &position(mesh, tri[1], moved, p),
                        &position(mesh, tri[2], moved, p)},
                       frames, corners))
      return false;
    sums += corners[k];
  }
  return true;
}

}  // namespace

Eigen::Vector3d quadratic_exactness_residual(const EditableMesh& mesh, std::uint32_t v, std::uint32_t moved,
                                             const Vec3& p) {
  MomentSums sums;
  if (!vertex_sums(mesh, v, TangentFrame(mesh.normals[v]), moved, p, sums))
    return Eigen::Vector3d::Constant(1e3);
  return residual_of(sums);
}

double laplacian_exactness_energy(const EditableMesh& mesh) {
  double energy = 0.0;
  for (std::uint32_t v = 0; v < mesh.vertex_slots(); ++v)
    if (mesh.alive(v) && !mesh.locked[v])
      energy += quadratic_exactness_residual(mesh, v, v, mesh.positions[v]).squaredNorm();
  return energy;
}

namespace {

/// What one move works with (one per thread).
struct Scratch {
  std::vector<std::uint32_t> ring;               ///< u's neighbours and u
  std::vector<std::size_t> corner_slot;          ///< [3 k + c]: ring index of corner c of u's k-th triangle
  std::vector<MomentSums> ring_sums;             ///< the ring's sums with u at the trial position
  std::vector<std::array<MomentSums, 3>> trial;  ///< corner sums of u's triangles at the last trial
  std::vector<std::array<TangentFrame, 3>> frames;  ///< the frames of the corners of u's triangles
  std::vector<std::array<MomentSums, 3>> current;   ///< corner sums of u's triangles as they are
  Eigen::VectorXd r0, r1;
  Eigen::VectorXd column[2];  ///< the Jacobian's columns (forward differences along e1, e2)
};

/// Gauss-Seidel sweeps with the moment sums of every vertex cached: a trial position of u only
/// recomputes u's triangles, once for all three corners, and adds the change to the cached sums of u
/// and its neighbours. The corners' current sums are recomputed once per move rather than cached per
/// triangle (the same numbers, so the same result, without 96 bytes per triangle).
class ExactnessSweeper {
 public:
  ExactnessSweeper(EditableMesh& mesh, const ExactnessMoveRules& rules)
      : mesh_(mesh), rules_(rules), floor_cosine_(std::cos(rules.angle_floor * std::numbers::pi / 180.0)) {
    std::vector<std::uint32_t> movable;
    for (std::uint32_t u = 0; u < mesh_.vertex_slots(); ++u)
      if (free(u)) movable.push_back(u);
    classes_ = mesh_.ring_disjoint_classes(movable);
  }

  /// One sweep: the vertices by classes whose rings are disjoint (a move rewrites the sums of its
  /// ring), each class in parallel: the same moves for any number of threads.
  std::size_t sweep() {
    refresh();
    std::atomic<std::size_t> kept{0};
    for (const std::vector<std::uint32_t>& members : classes_)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, members.size(), 64), [&](const auto& range) {
        Scratch& scratch = scratch_.local();
        std::size_t moved = 0;  // one shared increment per range, not per move
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          if (usable_[members[i]] && move(members[i], scratch)) ++moved;
        kept.fetch_add(moved, std::memory_order_relaxed);
      });
    return kept.load();
  }

 private:
  bool free(std::uint32_t v) const { return mesh_.alive(v) && !mesh_.locked[v]; }

  /// Frames, per-corner sums of every triangle and per-vertex sums from scratch, once per sweep (no
  /// drift of the updates). A vertex keeps its frame through the sweep even when it moves: all the
  /// sums of a sweep are taken in the same frames.
  void refresh() {
    const std::size_t n = mesh_.vertex_slots();
    frame_.resize(n), sums_.assign(n, MomentSums{}), usable_.assign(n, true);
    for (std::uint32_t v = 0; v < n; ++v)
      if (mesh_.alive(v)) frame_[v] = CompactTangentFrame(TangentFrame(mesh_.normals[v]));
    for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (!mesh_.triangle_alive[t]) continue;
      const Triangle& tri = mesh_.triangles[t];
      std::array<MomentSums, 3> corner;
      const TangentFrame frames[3] = {frame_[tri[0]].widen(), frame_[tri[1]].widen(), frame_[tri[2]].widen()};
      if (!triangle_sums({&mesh_.positions[tri[0]], &mesh_.positions[tri[1]], &mesh_.positions[tri[2]]},
                         {&frames[0], &frames[1], &frames[2]}, corner)) {
        for (std::uint32_t v : tri) usable_[v] = false;
        continue;
      }
      for (std::size_t c = 0; c < 3; ++c) sums_[tri[c]] += corner[c];
    }
  }

  /// The ring of u (its neighbours and u) with their residuals when u sits at q, stacked into `out`;
  /// the sums with u at q into ring_sums, the corner sums of u's triangles into trial. False when a
  /// triangle of u degenerates.
  bool evaluate(std::uint32_t u, const Vec3& q, Eigen::VectorXd& out, Scratch& s) const {
    const std::vector<std::uint32_t>& ring = s.ring;
    const std::vector<std::size_t>& corner_slot = s.corner_slot;
    std::vector<MomentSums>& ring_sums = s.ring_sums;
    std::vector<std::array<MomentSums, 3>>& trial = s.trial;
    for (std::size_t i = 0; i < ring.size(); ++i) ring_sums[i] = sums_[ring[i]];
    trial.resize(mesh_.incident[u].size());
    for (std::size_t k = 0; k < mesh_.incident[u].size(); ++k) {
      const std::uint32_t t = mesh_.incident[u][k];
      const Triangle& tri = mesh_.triangles[t];
      if (!triangle_sums({&position(mesh_, tri[0], u, q), &position(mesh_, tri[1], u, q),
                          &position(mesh_, tri[2], u, q)},
                         corner_frames(s.frames[k]), trial[k]))
        return false;
      for (std::size_t c = 0; c < 3; ++c) {
        MomentSums& sum = ring_sums[corner_slot[3 * k + c]];
        sum -= s.current[k][c];
        sum += trial[k][c];
      }
    }
    for (std::size_t i = 0; i < ring.size(); ++i)
      out.segment<3>(3 * static_cast<Eigen::Index>(i)) =
          free(ring[i]) ? residual_of(ring_sums[i]) : Eigen::Vector3d::Zero();
    return true;
  }

  /// ring: u's neighbours and u; corner_slot[3 k + c]: the ring index of corner c of u's k-th
  /// triangle; the frames and current corner sums of u's triangles. False when one is degenerate.
  bool collect_ring(std::uint32_t u, Scratch& s) const {
    std::vector<std::uint32_t>& ring = s.ring;
    std::vector<std::size_t>& corner_slot = s.corner_slot;
    ring.clear();
    const std::size_t triangles = mesh_.incident[u].size();
    corner_slot.resize(3 * triangles);
    s.frames.resize(triangles);
    s.current.resize(triangles);
    for (std::size_t k = 0; k < triangles; ++k) {
      const Triangle& tri = mesh_.triangles[mesh_.incident[u][k]];
      for (std::size_t c = 0; c < 3; ++c) {
        s.frames[k][c] = frame_[tri[c]].widen();
        const auto found = std::find(ring.begin(), ring.end(), tri[c]);
        corner_slot[3 * k + c] = static_cast<std::size_t>(found - ring.begin());
        if (found == ring.end()) ring.push_back(tri[c]);
      }
      if (!triangle_sums({&mesh_.positions[tri[0]], &mesh_.positions[tri[1]], &mesh_.positions[tri[2]]},
                         corner_frames(s.frames[k]), s.current[k]))
        return false;
    }
    return true;
  }

  bool move(std::uint32_t u, Scratch& s) {
    if (!collect_ring(u, s)) return false;
    const std::vector<std::uint32_t>& ring = s.ring;
    std::vector<MomentSums>& ring_sums = s.ring_sums;
    Eigen::VectorXd &r0 = s.r0, &r1 = s.r1;
    Eigen::VectorXd* column = s.column;
    ring_sums.resize(ring.size());
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(ring.size());
    r0.resize(rows), r1.resize(rows), column[0].resize(rows), column[1].resize(rows);
    for (std::size_t i = 0; i < ring.size(); ++i)
      r0.segment<3>(3 * static_cast<Eigen::Index>(i)) =
          free(ring[i]) ? residual_of(sums_[ring[i]]) : Eigen::Vector3d::Zero();
    const double before = r0.squaredNorm();
    const Vec3 p = mesh_.positions[u];
    const Vec3 n = mesh_.normals[u];
    const TangentFrame f = frame_[u].widen();
    const double h = rules_.size(u);
    const double delta = 1e-4 * h;
    for (int k = 0; k < 2; ++k) {
      if (!evaluate(u, p + delta * (k == 0 ? f.e1 : f.e2), r1, s)) return false;
      column[k] = (r1 - r0) / delta;
    }
    // Normal equations of the 2-column Jacobian, slightly damped.
    Eigen::Matrix2d normal;
    normal(0, 0) = column[0].squaredNorm();
    normal(1, 1) = column[1].squaredNorm();
    normal(0, 1) = normal(1, 0) = column[0].dot(column[1]);
    normal.diagonal().array() += 1e-9 * normal.trace() + 1e-300;
    Eigen::Vector2d step = -normal.ldlt().solve(Eigen::Vector2d(column[0].dot(r0), column[1].dot(r0)));
    if (!step.allFinite()) return false;
    if (step.norm() > 0.2 * h) step *= 0.2 * h / step.norm();
    // The floor as the cosine of an angle: no smallest angle may fall below min(its own, the floor).
    double floor_cosine = floor_cosine_;
    for (std::uint32_t t : mesh_.incident[u]) floor_cosine = std::max(floor_cosine, angle_cosine(t, u, p));
    for (int halving = 0; halving < 4; ++halving, step *= 0.5) {
      Vec3 q = p + step[0] * f.e1 + step[1] * f.e2;
      Vec3 nq = n;
      if (!rules_.project(q, nq, step.norm() + h)) return false;
      if (!evaluate(u, q, r1, s) || !(r1.squaredNorm() < before)) continue;
      bool valid = true;
      for (std::uint32_t t : mesh_.incident[u])
        if (!rules_.triangle_valid(t, u, q, nq) || angle_cosine(t, u, q) > floor_cosine) {
          valid = false;
          break;
        }
      if (!valid) continue;
      mesh_.positions[u] = q;
      mesh_.normals[u] = nq;
      for (std::size_t i = 0; i < ring.size(); ++i) sums_[ring[i]] = ring_sums[i];
      for (std::size_t k = 0; k < mesh_.incident[u].size(); ++k) return true;
    }
    return false;
  }

  /// Cosine of the smallest angle of triangle t with vertex u at q (a larger cosine: a smaller angle).
  double angle_cosine(std::uint32_t t, std::uint32_t u, const Vec3& q) const {
    const Triangle& tri = mesh_.triangles[t];
    return smallest_angle_cosine(position(mesh_, tri[0], u, q), position(mesh_, tri[1], u, q),
                                 position(mesh_, tri[2], u, q));
  }

  EditableMesh& mesh_;
  const ExactnessMoveRules& rules_;
  double floor_cosine_;
  std::vector<CompactTangentFrame>
      frame_;                     ///< per vertex slot: tangent frame of its normal at the sweep's start
  std::vector<MomentSums> sums_;  ///< per vertex slot: moment sums in that frame
  std::vector<bool> usable_;      ///< per vertex slot: no degenerate triangle around it
  std::vector<std::vector<std::uint32_t>> classes_;  ///< free vertices, by classes of disjoint rings
  tbb::enumerable_thread_specific<Scratch> scratch_;
};

}  // namespace

std::size_t improve_laplacian_exactness(EditableMesh& mesh, const ExactnessMoveRules& rules, int sweeps) {
  ExactnessSweeper sweeper(mesh, rules);
  std::size_t kept = 0;
  for (int s = 0; s < sweeps; ++s) {
    if (rules.before_sweep) rules.before_sweep();
    kept += sweeper.sweep();
  }
  return kept;
}

}  // namespace isopatch
