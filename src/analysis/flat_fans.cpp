// mesh_fans and flat_fans (flat_fans.hpp).
#include "analysis/flat_fans.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "analysis/mesh_neighbourhood.hpp"
#include "analysis/segments_2d.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace isopatch::analysis {
namespace {

/// Fans of more triangles are left unproved (the pairs are then tested one by one).
constexpr std::size_t kLongestFan = 64;

/// The triangles at each vertex: offsets into one array (compressed rows).
struct Incidence {
  std::vector<std::uint32_t> offsets;  // vertex count + 1
  UninitialisedVector<std::uint32_t> triangles;
};

Incidence incidence(const Mesh& mesh) {
  Incidence in;
  in.offsets.assign(mesh.positions.size() + 1, 0);
  for (const Triangle& t : mesh.triangles)
    if (!repeats_vertex(t))
      for (const std::uint32_t v : t) ++in.offsets[v + 1];
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) in.offsets[v + 1] += in.offsets[v];
  in.triangles.resize(in.offsets.back());
  std::vector<std::uint32_t> next(in.offsets.begin(), in.offsets.end() - 1);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Triangle& t = mesh.triangles[i];
    if (!repeats_vertex(t))
      for (const std::uint32_t v : t) in.triangles[next[v]++] = static_cast<std::uint32_t>(i);
  }
  return in;
}

/// The turn bits of MeshFans::triangle_turns for triangle t.
std::uint8_t turn_bits(const Mesh& mesh, const Triangle& t) {
  if (repeats_vertex(t)) return 0;
  std::uint8_t bits = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int s = orient2d(drop_axis(mesh.positions[t[0]], axis), drop_axis(mesh.positions[t[1]], axis),
                           drop_axis(mesh.positions[t[2]], axis));
    if (s > 0) bits |= static_cast<std::uint8_t>(1U << axis);
    if (s < 0) bits |= static_cast<std::uint8_t>(8U << axis);
  }
  return bits;
}

/// Position (0, 1, 2) of v in t.
int corner(const Triangle& t, std::uint32_t v) {
  return t[0] == v ? 0 : (t[1] == v ? 1 : 2);
}

/// The other two vertices of triangle t in its own cyclic order after v: t = (v, a, b) rotated.
std::array<std::uint32_t, 2> after(const Triangle& t, std::uint32_t v) {
  const int k = corner(t, v);
  return {t[static_cast<std::size_t>((k + 1) % 3)], t[static_cast<std::size_t>((k + 2) % 3)]};
}

/// The neighbour of triangle t across its edge from a to b (MeshFans::neighbours), from the triangles
/// at a: for the fans too long for neighbours_at.
std::uint32_t neighbour(const Mesh& mesh, const Incidence& in, std::uint32_t t, std::uint32_t a,
                        std::uint32_t b) {
  std::uint32_t found = MeshFans::kOpen;
  for (std::uint32_t k = in.offsets[a]; k < in.offsets[a + 1]; ++k) {
    const std::uint32_t u = in.triangles[k];
    if (u == t) continue;
    const Triangle& other = mesh.triangles[u];
    const int at = corner(other, a);
    const std::uint32_t next = other[static_cast<std::size_t>((at + 1) % 3)];
    const std::uint32_t previous = other[static_cast<std::size_t>((at + 2) % 3)];
    if (next == b) return MeshFans::kTangled;  // the same direction as in t
    if (previous != b) continue;
    if (found != MeshFans::kOpen) return MeshFans::kTangled;  // a third triangle on the edge
    found = u;
  }
  return found;
}

/// The index in t of its edge that ends at v (t[e] to t[e + 1] with t[e + 1] = v).
std::size_t edge_into(const Triangle& t, std::uint32_t v) {
  return static_cast<std::size_t>((corner(t, v) + 2) % 3);
}

/// The proof of flat_fans.hpp for vertex v with the wedges `wedges` (a_i, a_{i+1}) of the triangles
/// `triangle`, projected along `axis`.
bool winds_once(const Mesh& mesh, std::uint32_t v, const std::array<std::uint32_t, 2>* wedges,
                const std::uint32_t* triangle, std::size_t n, const std::vector<std::uint8_t>& turns,
                int axis) {
  const auto positive = static_cast<std::uint8_t>(1U << static_cast<unsigned>(axis));
  const auto negative = static_cast<std::uint8_t>(8U << static_cast<unsigned>(axis));
  const auto turn = static_cast<std::uint8_t>(turns[triangle[0]] & (positive | negative));
  if (turn == 0) return false;
  const int j = (axis + 2) % 3;
  const Vec3& p = mesh.positions[v];
  int crossings = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if ((turns[triangle[k]] & turn) == 0) return false;
    // The wedge from a to b (counter-clockwise when positive) holds the direction of the first kept
    // axis when it goes from below p (or level with it) to above, in the order of its turn.
    const Vec3& from = mesh.positions[wedges[k][turn == positive ? 0 : 1]];
    const Vec3& to = mesh.positions[wedges[k][turn == positive ? 1 : 0]];
    if (from[j] <= p[j] && to[j] > p[j]) ++crossings;
  }
  return crossings == 1;
}

/// At vertex v: writes the neighbours across the edges of its triangles that end at v.
void neighbours_at(const Mesh& mesh, const Incidence& in, std::uint32_t v,
                   UninitialisedVector<std::uint32_t>& neighbours) {
  const std::uint32_t* triangle = in.triangles.data() + in.offsets[v];
  const std::size_t n = in.offsets[v + 1] - in.offsets[v];
  if (n > kLongestFan) {
    for (std::size_t k = 0; k < n; ++k) {
      const Triangle& t = mesh.triangles[triangle[k]];
      const std::size_t e = edge_into(t, v);
      neighbours[3 * std::size_t{triangle[k]} + e] = neighbour(mesh, in, triangle[k], t[e], v);
    }
    return;
  }
  // Triangle k is (v, a_k, b_k); the triangle across its edge from b_k into v is the one whose a is b_k,
  // unless two are (a third triangle on the edge) or another's b is b_k too (the same edge the same
  // way). Counted without branches: the inner loop was most of this function's time.
  std::array<std::uint32_t, kLongestFan> a{}, b{};
  std::array<std::uint8_t, kLongestFan> into{};
  for (std::size_t k = 0; k < n; ++k) {
    const Triangle& t = mesh.triangles[triangle[k]];
    const int c = corner(t, v);
    a[k] = t[static_cast<std::size_t>((c + 1) % 3)];
    b[k] = t[static_cast<std::size_t>((c + 2) % 3)];
    into[k] = static_cast<std::uint8_t>((c + 2) % 3);
  }
  for (std::size_t k = 0; k < n; ++k) {
    unsigned starts = 0, ends = 0;
    std::size_t match = 0;
    for (std::size_t m = 0; m < n; ++m) {
      const bool start = a[m] == b[k];
      starts += start ? 1U : 0U;
      ends += b[m] == b[k] ? 1U : 0U;  // k itself once
      match = start ? m : match;
    }
    neighbours[3 * std::size_t{triangle[k]} + into[k]] =
        starts == 0 ? MeshFans::kOpen : (starts == 1 && ends == 1 ? triangle[match] : MeshFans::kTangled);
  }
}

}  // namespace

MeshFans mesh_fans(const Mesh& mesh) {
  MeshFans out;
  out.triangle_turns.assign(mesh.triangles.size(), 0);
  // Every neighbour is written once: those of triangles that repeat an index here, the others from the
  // fans of their three corners (the edges into them).
  out.neighbours.resize(3 * mesh.triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.triangles.size(), 8192), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      out.triangle_turns[t] = turn_bits(mesh, mesh.triangles[t]);
      if (repeats_vertex(mesh.triangles[t]))
        for (std::size_t e = 0; e < 3; ++e) out.neighbours[3 * t + e] = MeshFans::kOpen;
    }
  });
  const Incidence in = incidence(mesh);
  out.first_triangles.assign(mesh.positions.size(), MeshFans::kOpen);
  out.fan_sizes.assign(mesh.positions.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      const std::uint32_t n = in.offsets[v + 1] - in.offsets[v];
      if (n == 0) continue;
      out.first_triangles[v] = in.triangles[in.offsets[v]];
      out.fan_sizes[v] = static_cast<std::uint8_t>(std::min(n, 255U));
      neighbours_at(mesh, in, static_cast<std::uint32_t>(v), out.neighbours);
    }
  });
  return out;
}

bool flat_fan(const Mesh& mesh, const MeshFans& fans, std::uint32_t v) {
  const std::size_t n = fans.fan_sizes[v];
  if (n < 3 || n > kLongestFan) return false;
  const std::uint32_t first = fans.first_triangles[v];
  std::array<std::array<std::uint32_t, 2>, kLongestFan> wedge{};
  std::array<std::uint32_t, kLongestFan> triangle{};
  std::uint32_t t = first;
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0 && t == first) return false;  // a cycle of fewer: the fan has another
    const Triangle& tri = mesh.triangles[t];
    triangle[k] = t;
    wedge[k] = after(tri, v);
    t = fans.neighbours[3 * std::size_t{t} + edge_into(tri, v)];
    if (t == MeshFans::kOpen || t == MeshFans::kTangled) return false;
  }
  if (t != first) return false;
  // The axis where the fan's normal is largest first, then the others.
  Vec3 normal = Vec3::Zero();
  const Vec3& p = mesh.positions[v];
  for (std::size_t k = 0; k < n; ++k)
    normal += (mesh.positions[wedge[k][0]] - p).cross(mesh.positions[wedge[k][1]] - p);
  const Vec3 size = normal.cwiseAbs();
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(), [&](int a, int b) { return size[a] > size[b]; });
  for (const int axis : axes)
    if (winds_once(mesh, v, wedge.data(), triangle.data(), n, fans.triangle_turns, axis)) return true;
  return false;
}

std::vector<std::uint8_t> flat_fans(const Mesh& mesh) {
  const MeshFans fans = mesh_fans(mesh);
  std::vector<std::uint8_t> out(mesh.positions.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v)
      out[v] = flat_fan(mesh, fans, static_cast<std::uint32_t>(v)) ? 1 : 0;
  });
  return out;
}

}  // namespace isopatch::analysis
