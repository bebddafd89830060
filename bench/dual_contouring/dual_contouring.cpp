// Plain Dual Contouring on a uniform grid (Ju, Losasso, Schaefer & Warren, "Dual contouring of
// Hermite data", SIGGRAPH 2002): sampling, Hermite data on the sign-changing edges, one QEF vertex per
// cell and one quad per edge. See dual_contouring.hpp.
#include "dual_contouring.hpp"

#include <isopatch/error.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "qef.hpp"

namespace isopatch::bench {
namespace {

using Clock = std::chrono::steady_clock;
using Index3 = std::array<int, 3>;

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

// The cells around an edge along axis a, as offsets along the next two axes (b, c) = (a+1, a+2) mod 3:
// counter-clockwise in the (b, c) plane, so a quad in this order faces +a (b x c = a).
constexpr std::array<std::array<int, 2>, 4> kCellsAroundEdge{{{-1, -1}, {0, -1}, {0, 0}, {-1, 0}}};

// Inside is f < 0; zero and positive (and non-finite, replaced by +1) are outside.
bool inside(double value) {
  return value < 0.0;
}

// The uniform grid: n[a] cubic cells of side `spacing` along axis a from `lo`, n[a] + 1 corners.
struct Grid {
  Vec3 lo = Vec3::Zero();
  double spacing = 0.0;
  Index3 n{};

  std::size_t corner_count(int axis) const {
    return static_cast<std::size_t>(n[static_cast<std::size_t>(axis)]) + 1;
  }
  // Corners and cells are numbered x fastest, then y, then z.
  std::size_t corner_index(const Index3& p) const {
    return static_cast<std::size_t>(p[0]) +
           corner_count(0) *
               (static_cast<std::size_t>(p[1]) + corner_count(1) * static_cast<std::size_t>(p[2]));
  }
  std::size_t corner_stride(int axis) const {
    return axis == 0 ? 1 : axis == 1 ? corner_count(0) : corner_count(0) * corner_count(1);
  }
  std::size_t cell_index(const Index3& c) const {
    const auto nx = static_cast<std::size_t>(n[0]);
    const auto ny = static_cast<std::size_t>(n[1]);
    return static_cast<std::size_t>(c[0]) +
           nx * (static_cast<std::size_t>(c[1]) + ny * static_cast<std::size_t>(c[2]));
  }
  std::size_t cell_count() const {
    return static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]);
  }
  Vec3 corner(const Index3& p) const { return lo + spacing * Vec3(p[0], p[1], p[2]); }
};

Grid make_grid(const Box& box, int cells) {
  Grid g;
  g.lo = box.lo;
  g.spacing = box.size().maxCoeff() / cells;
  for (int axis = 0; axis < 3; ++axis)
    g.n[static_cast<std::size_t>(axis)] =
        std::max(1, static_cast<int>(std::ceil(box.size()[axis] / g.spacing - 1e-9)));
  return g;
}

// Counts of the evaluations of f, for the result.
struct Counters {
  std::size_t values = 0;
  std::size_t gradients = 0;
  std::size_t non_finite = 0;
};

double checked(double value, Counters& counters) {
  if (std::isfinite(value)) return value;
  ++counters.non_finite;
  return 1.0;
}

// f at every grid corner, one z-slice per batch evaluation (Surface::values).
std::vector<double> sample_corners(const Surface& surface, const Grid& g, Counters& counters) {
  const std::size_t slice = g.corner_count(0) * g.corner_count(1);
  std::vector<double> values(slice * g.corner_count(2));
  std::vector<Vec3> points(slice);
  for (int k = 0; k <= g.n[2]; ++k) {
    std::size_t i = 0;
    for (int y = 0; y <= g.n[1]; ++y)
      for (int x = 0; x <= g.n[0]; ++x) points[i++] = g.corner({x, y, k});
    const std::span<double> out(values.data() + static_cast<std::size_t>(k) * slice, slice);
    surface.values(points, out);
    for (double& v : out) v = checked(v, counters);
  }
  counters.values += values.size();
  return values;
}

// The point where f = 0 on the segment a -> b, whose ends (values fa, fb) differ in sign: `steps` steps
// of false position with the Illinois modification (the bracket's stale end has its value halved), then
// the false-position point of the final bracket.
Vec3 locate_crossing(const Surface& surface, const Vec3& a, const Vec3& b, double fa, double fb, int steps,
                     Counters& counters) {
  double t0 = 0.0;
  double t1 = 1.0;
  double g0 = fa;
  double g1 = fb;
  const bool inside0 = inside(fa);
  int kept = -1;  // the end the previous step kept (0 or 1)
  for (int step = 0; step < steps; ++step) {
    const double t = std::clamp(t0 + (t1 - t0) * (g0 / (g0 - g1)), t0, t1);
    const double g = checked(surface.value(a + t * (b - a)), counters);
    ++counters.values;
    if (g == 0.0) return a + t * (b - a);
    if (inside(g) == inside0) {
      t0 = t;
      g0 = g;
      if (kept == 1) g1 *= 0.5;
      kept = 1;
    } else {
      t1 = t;
      g1 = g;
      if (kept == 0) g0 *= 0.5;
      kept = 0;
    }
  }
  const double t = std::clamp(t0 + (t1 - t0) * (g0 / (g0 - g1)), t0, t1);
  return a + t * (b - a);
}

// The unit normal grad f / |grad f| at p, or the zero vector where the gradient is zero or not finite.
Vec3 unit_normal(const Surface& surface, const Vec3& p, Counters& counters) {
  const Vec3 gradient = surface.value_gradient(p).gradient;
  ++counters.gradients;
  const double length = gradient.norm();
  if (!std::isfinite(length) || !(length > 0.0)) return Vec3::Zero();
  return gradient / length;
}

// One vertex per cell whose corners differ in sign (exactly the cells with a sign-changing edge),
// numbered in cell order; returns the cell of each vertex and fills cell_vertex.
std::vector<Index3> number_cells(const Grid& g, const std::vector<double>& values,
                                 std::vector<std::uint32_t>& cell_vertex) {
  cell_vertex.assign(g.cell_count(), kNoVertex);
  std::vector<Index3> vertex_cell;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        int inside_corners = 0;
        for (int corner = 0; corner < 8; ++corner)
          inside_corners += inside(values[g.corner_index(
                                {i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1)})])
                                ? 1
                                : 0;
        if (inside_corners == 0 || inside_corners == 8) continue;
        if (vertex_cell.size() >= kNoVertex) throw InputError("dual contouring: too many vertices");
        cell_vertex[g.cell_index({i, j, k})] = static_cast<std::uint32_t>(vertex_cell.size());
        vertex_cell.push_back({i, j, k});
      }
  return vertex_cell;
}

using Quad = std::array<std::uint32_t, 4>;

// Two triangles per quad, split along the shorter diagonal (the first one on a tie).
void triangulate(const std::vector<Quad>& quads, Mesh& mesh) {
  mesh.triangles.reserve(2 * quads.size());
  for (const Quad& q : quads) {
    const auto& p = mesh.positions;
    if ((p[q[0]] - p[q[2]]).squaredNorm() <= (p[q[1]] - p[q[3]]).squaredNorm()) {
      mesh.triangles.push_back({q[0], q[1], q[2]});
      mesh.triangles.push_back({q[0], q[2], q[3]});
    } else {
      mesh.triangles.push_back({q[0], q[1], q[3]});
      mesh.triangles.push_back({q[1], q[2], q[3]});
    }
  }
}

}  // namespace

DualContouringResult dual_contouring(const Surface& surface, const Box& box,
                                     const DualContouringOptions& options) {
  if (!box.valid()) throw InputError("dual contouring: invalid box");
  if (options.cells < 1 || options.crossing_steps < 0 ||
      !(options.truncation >= 0.0 && options.truncation < 1.0))
    throw InputError("dual contouring needs cells >= 1, crossing_steps >= 0 and 0 <= truncation < 1");
  const auto start = Clock::now();
  DualContouringResult r;
  const Grid g = make_grid(box, options.cells);
  r.cells = options.cells;
  r.grid = g.n;
  r.spacing = g.spacing;
  Counters counters;
  const std::vector<double> values = sample_corners(surface, g, counters);
  std::vector<std::uint32_t> cell_vertex;
  const std::vector<Index3> vertex_cell = number_cells(g, values, cell_vertex);
  std::vector<Qef> qefs(vertex_cell.size());

  // Hermite data on every sign-changing edge, added to the QEF of each cell around it (points relative
  // to the cell's lowest corner); a quad where all four cells exist (edges on the grid's boundary have
  // fewer and no quad).
  std::vector<Quad> quads;
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    const int c = (a + 2) % 3;
    const auto ua = static_cast<std::size_t>(a);
    const auto ub = static_cast<std::size_t>(b);
    const auto uc = static_cast<std::size_t>(c);
    Index3 end{g.n[0] + 1, g.n[1] + 1, g.n[2] + 1};
    end[ua] = g.n[ua];
    for (int k = 0; k < end[2]; ++k)
      for (int j = 0; j < end[1]; ++j)
        for (int i = 0; i < end[0]; ++i) {
          const Index3 p{i, j, k};
          const std::size_t c0 = g.corner_index(p);
          const double f0 = values[c0];
          const double f1 = values[c0 + g.corner_stride(a)];
          if (inside(f0) == inside(f1)) continue;
          Index3 q = p;
          ++q[ua];
          const Vec3 x =
              locate_crossing(surface, g.corner(p), g.corner(q), f0, f1, options.crossing_steps, counters);
          const Vec3 normal = unit_normal(surface, x, counters);
          Quad quad{};
          bool complete = true;
          for (std::size_t around = 0; around < 4; ++around) {
            Index3 cell = p;
            cell[ub] += kCellsAroundEdge[around][0];
            cell[uc] += kCellsAroundEdge[around][1];
            if (cell[ub] < 0 || cell[ub] >= g.n[ub] || cell[uc] < 0 || cell[uc] >= g.n[uc]) {
              complete = false;
              continue;
            }
            const std::uint32_t vertex = cell_vertex[g.cell_index(cell)];  // the cell has this edge
            qefs[vertex].add(x - g.corner(cell), normal);
            quad[around] = vertex;
          }
          if (!complete) {
            ++r.boundary_edges;
            continue;
          }
          // The quad faces +a; outside (f >= 0) must be in front of it.
          if (!inside(f0)) std::swap(quad[1], quad[3]);
          quads.push_back(quad);
        }
  }

  // Each vertex at its QEF's minimiser, clamped to its cell: plain DC, as users of libfive-like tools
  // get it. A minimiser outside the cell (common near creases and thin parts) is pulled back onto the
  // cell's boundary, which keeps the vertex near its cell but does not prevent folds: the output may
  // self-intersect.
  r.mesh.positions.reserve(vertex_cell.size());
  for (std::size_t v = 0; v < vertex_cell.size(); ++v) {
    Vec3 local = qefs[v].minimiser(options.truncation);
    if (!local.allFinite()) local = qefs[v].mass_point();
    const Vec3 clamped = local.cwiseMax(0.0).cwiseMin(g.spacing);
    if (clamped != local) ++r.clamped_vertices;
    r.mesh.positions.push_back(g.corner(vertex_cell[v]) + clamped);
  }
  triangulate(quads, r.mesh);
  r.value_evaluations = counters.values;
  r.gradient_evaluations = counters.gradients;
  r.non_finite_values = counters.non_finite;
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.search_seconds = r.seconds;
  return r;
}

}  // namespace isopatch::bench
