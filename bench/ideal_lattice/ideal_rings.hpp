#pragma once
// The curvature error a perfect lattice would leave: at each sample point of a surface, a regular
// hexagon of equilateral triangles (in the tangent plane, lifted onto f = 0 along the normal) and the
// cotangent mean curvature of its centre (Meyer, Desbrun, Schroeder, Barr 2003, as the analysis
// computes it) against the exact H. The reference the quality report sets beside a measured H nRMS:
// what a mesh of ideal valence-6 rings with the same vertex count would give, at every orientation of
// the lattice. Not a lower bound for every mesh (non-equilateral rings can cancel part of the error),
// a yardstick for what equilateral triangles of a given size allow.

#include <isopatch/mesh.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>

namespace isopatch::bench {

/// How the ring's edge length varies over the surface.
enum class RingSizes {
  Uniform,  ///< one edge length: that of an equilateral mesh with the mesh's area and vertex count
  Graded,   ///< c / sqrt(kappa_max), the law of `--max-error`, c from the same area and vertex count
};

struct IdealRingOptions {
  RingSizes sizes = RingSizes::Uniform;
  int orientations = 6;             ///< lattice angles k * 60 / orientations degrees, k = 0 .. orientations-1
  std::size_t max_samples = 10000;  ///< at most this many interior vertices (evenly strided)
};

struct IdealRingResult {
  double nrms_mean = 0.0;   ///< sqrt(sum of the mean squared error over orientations / sum H^2)
  double nrms_best = 0.0;   ///< the same with each sample's best orientation
  double edge = 0.0;        ///< Uniform: the edge length; Graded: c of c / sqrt(kappa)
  std::size_t samples = 0;  ///< sample points used
  std::size_t skipped = 0;  ///< sample points where no orientation's ring could be lifted (no surface
                            ///< point above a ring vertex within one edge length: the ring is longer
                            ///< than the surface is wide there) or H is not finite
};

/// The error of ideal rings centred at the interior vertices of `mesh` (which lie on `surface`), sized
/// from the mesh's total area and vertex count as `options.sizes` says.
/// \throw InputError when the mesh has no interior vertex or no area, orientations < 1 or
///        max_samples < 1.
IdealRingResult ideal_ring_error(const Mesh& mesh, const Surface& surface, const IdealRingOptions& options);

}  // namespace isopatch::bench
