// flat_fans (flat_fans.hpp).
#include "analysis/flat_fans.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "analysis/exact_predicates.hpp"
#include "analysis/mesh_neighbourhood.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace isopatch::analysis {
namespace {

/// Fans of more triangles are left unproved (the pairs are then tested one by one).
constexpr std::size_t kLongestFan = 64;

/// The triangles at each vertex: offsets into one array (compressed rows).
struct Incidence {
  std::vector<std::uint32_t> offsets;  // vertex count + 1
  std::vector<std::uint32_t> triangles;
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

/// The other two vertices of triangle t in its own cyclic order after v: t = (v, a, b) rotated.
std::array<std::uint32_t, 2> after(const Triangle& t, std::uint32_t v) {
  const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
  return {t[static_cast<std::size_t>((k + 1) % 3)], t[static_cast<std::size_t>((k + 2) % 3)]};
}

/// The proof of flat_fans.hpp for vertex v with the wedges `wedges` (a_i, a_{i+1}), in cyclic order,
/// projected along `axis`.
bool winds_once(const Mesh& mesh, std::uint32_t v, const std::array<std::uint32_t, 2>* wedges, std::size_t n,
                int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const Vec3& p = mesh.positions[v];
  int sign = 0, crossings = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& a = mesh.positions[wedges[k][0]];
    const Vec3& b = mesh.positions[wedges[k][1]];
    const int s = exact::orient2d(p[i], p[j], a[i], a[j], b[i], b[j]);
    if (s == 0 || (sign != 0 && s != sign)) return false;
    sign = s;
    // The wedge from a to b (counter-clockwise when sign > 0) holds the direction +i when it goes from
    // below p (or level with it) to above, in the order of its turn.
    const Vec3& from = sign > 0 ? a : b;
    const Vec3& to = sign > 0 ? b : a;
    if (from[j] <= p[j] && to[j] > p[j]) ++crossings;
  }
  return crossings == 1;
}

bool flat_fan(const Mesh& mesh, const Incidence& in, std::uint32_t v) {
  const std::uint32_t* first = in.triangles.data() + in.offsets[v];
  const std::size_t n = in.offsets[v + 1] - in.offsets[v];
  if (n < 3 || n > kLongestFan) return false;
  std::array<std::array<std::uint32_t, 2>, kLongestFan> wedge{};
  for (std::size_t k = 0; k < n; ++k) wedge[k] = after(mesh.triangles[first[k]], v);
  // Order the wedges into one cycle: each wedge's end is the next one's start.
  for (std::size_t k = 0; k + 1 < n; ++k) {
    std::size_t found = n;
    for (std::size_t m = k + 1; m < n; ++m)
      if (wedge[m][0] == wedge[k][1]) {
        if (found != n) return false;  // two wedges start there: not one cycle
        found = m;
      }
    if (found == n) return false;
    std::swap(wedge[k + 1], wedge[found]);
  }
  if (wedge[n - 1][1] != wedge[0][0]) return false;
  for (std::size_t k = 0; k < n; ++k)  // each neighbour once: one cycle, not a figure eight
    for (std::size_t m = k + 1; m < n; ++m)
      if (wedge[m][0] == wedge[k][0]) return false;
  // The axis where the fan's normal is largest first, then the others.
  Vec3 normal = Vec3::Zero();
  const Vec3& p = mesh.positions[v];
  for (std::size_t k = 0; k < n; ++k)
    normal += (mesh.positions[wedge[k][0]] - p).cross(mesh.positions[wedge[k][1]] - p);
  const Vec3 size = normal.cwiseAbs();
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(), [&](int a, int b) { return size[a] > size[b]; });
  for (const int axis : axes)
    if (winds_once(mesh, v, wedge.data(), n, axis)) return true;
  return false;
}

}  // namespace

std::vector<std::uint8_t> flat_fans(const Mesh& mesh) {
  const Incidence in = incidence(mesh);
  std::vector<std::uint8_t> proved(mesh.positions.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.positions.size(), 4096), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v)
      proved[v] = flat_fan(mesh, in, static_cast<std::uint32_t>(v)) ? 1 : 0;
  });
  return proved;
}

}  // namespace isopatch::analysis
