#pragma once
// Relaxation of a refined mesh on f = 0: Jacobi sweeps of tangential uniform-Laplacian moves (each
// free vertex moved part of the way to the centroid of its ring, within its tangent plane), every moved
// vertex put back on f = 0 by Newton steps; a vertex on a cut boundary slides along the curve where its
// plane meets f = 0 towards the midpoint of its two neighbours on that curve. A sweep goes through
// fixed blocks of vertices in turn; within a block it reads only the positions before it (Jacobi), so
// the result does not depend on the threads, and its buffers hold one block, not the whole mesh. A move is
// undone when its projection fails or when it leaves a triangle turned away from the surface (the same
// validity test as the clean-up: the triangle's normal within about 72 degrees of the surface normal at each
// corner). On a mesh made of pieces (a composite surface) every vertex is put back on its own piece's
// function.

#include <isopatch/mesh.hpp>

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "refine/base_edges.hpp"
#include "refine/batched_newton.hpp"
#include "refine/lattice_layout.hpp"
#include "refine/vertex_rings.hpp"

namespace isopatch::refine {

/// How a vertex may move.
enum class Motion : std::uint8_t { Free, Slides, Locked };

/// Share of the way to the ring centroid that one sweep moves a free vertex (a full step oscillates on
/// a regular lattice; half of it smooths the lattice's longest wavelengths fastest without).
inline constexpr double kRelaxationStep = 0.5;
/// Vertices per block of a sweep: blocks are relaxed one after the other (each in parallel), so a sweep's
/// buffers take about 40 bytes per block vertex rather than per mesh vertex, while a block still gives
/// every worker hundreds of tasks. A fixed number, so the blocks and the result are the same for any
/// number of threads.
inline constexpr std::size_t kSweepBlock = std::size_t{1} << 17;

class LatticeRelaxation {
 public:
  /// \param mesh        the refined mesh, every vertex on f = 0; positions are moved in place
  /// \param normals     unit grad f at every vertex (kept up to date)
  /// \param motion      per vertex
  /// \param edge_plane  per base edge: the cut plane its points slide on (boundary edges), or -1
  /// \param functions   the functions the vertices lie on (one, or one per piece); they outlive this
  /// \param vertex_function  per vertex: its index into `functions` (empty: every vertex on the first)
  /// \param limits      the Newton limits of every re-projection
  /// \param block       vertices per block of a sweep (>= 1)
  LatticeRelaxation(Mesh& mesh, std::vector<Eigen::Vector3f>& normals, const std::vector<Motion>& motion,
                    const LatticeLayout& layout, const BaseEdges& edges, const std::vector<int>& edge_plane,
                    std::span<const Sampler* const> functions,
                    const std::vector<std::uint32_t>& vertex_function, const BoundaryPlanes& planes,
                    const NewtonLimits& limits, std::size_t block = kSweepBlock);

  /// From now on, undo a move that leaves a triangle with a smallest angle under `degrees` and smaller
  /// than before the move (0: no such guard).
  void set_angle_guard(double degrees) { angle_guard_ = degrees; }

  /// One sweep over every vertex that may move, or only over those with (*subset)[v] set.
  /// Returns the moves undone.
  std::size_t sweep(const std::vector<std::uint8_t>* subset = nullptr);

 private:
  /// The target of vertex v before projection, or false when v does not move.
  bool target(std::uint32_t v, Vec3& to, int& plane) const;
  /// One sweep over the vertices [begin, end); returns the moves undone.
  std::size_t sweep_block(std::size_t begin, std::size_t end, const std::vector<std::uint8_t>* subset);

  Mesh& mesh_;
  std::vector<Eigen::Vector3f>& normals_;
  const std::vector<Motion>& motion_;
  const LatticeLayout& layout_;
  const BaseEdges& edges_;
  const std::vector<int>& edge_plane_;
  std::span<const Sampler* const> functions_;
  const std::vector<std::uint32_t>& vertex_function_;
  const BoundaryPlanes& planes_;
  NewtonLimits limits_;
  std::size_t block_;
  double angle_guard_ = 0.0;
  VertexRings rings_;
  // The triangles with a corner in each block (compressed rows, ascending): the only ones a block's
  // moves can turn. About 6 bytes per triangle.
  std::vector<std::uint32_t> block_offsets_;
  std::vector<std::uint32_t> block_triangles_;
  // One block's results (indexed from the block's first vertex), kept between blocks and sweeps so
  // that each does not allocate them again; invalid_ flags the block's triangles.
  std::vector<Vec3> next_;
  std::vector<Eigen::Vector3f> next_normals_;
  std::vector<std::uint8_t> moved_;
  std::vector<std::uint8_t> invalid_;
};

/// Whether triangle t of `positions` faces the surface: its normal within about 72 degrees of the unit
/// surface normal at each corner (the clean-up's validity test, remesh_thresholds.hpp kMinNormalDot);
/// false for a degenerate triangle.
bool faces_the_surface(const std::vector<Vec3>& positions, const std::vector<Eigen::Vector3f>& normals,
                       const Triangle& t);
/// The same for the triangle (a, b, c) with the unit surface normals at its corners.
bool faces_the_surface(const Vec3& a, const Vec3& b, const Vec3& c,
                       const std::array<Eigen::Vector3f, 3>& corner_normals);

/// Smallest angle of triangle t of `mesh`, in degrees (0 for a degenerate triangle).
double smallest_angle_degrees(const Mesh& mesh, const Triangle& t);

/// Smallest angle of any triangle of `mesh`, in degrees (180 without triangles). Parallel; the same
/// value for any thread count (a minimum).
double smallest_angle_degrees(const Mesh& mesh);

}  // namespace isopatch::refine
