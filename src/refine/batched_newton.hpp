#pragma once
// Putting many points on f = 0 at once: Newton steps along grad f (x <- x - f g / |g|^2, the
// closest-point iteration of a level set), or, for a point held on a cut plane, along the part of grad f
// within that plane (the point then ends on the curve where the plane meets f = 0). Every round
// evaluates value and gradient of all points still moving in one batch (Sampler::value_gradients). Each
// point's iterates depend on its own start alone, so the result is the same however the points are
// grouped into batches or threads. A mesh made of pieces, each on its own function (the patches of a
// composite surface), lands every point on its own piece's function; the points of each piece are
// evaluated in one batch per round.

#include <isopatch/geometry.hpp>

#include <cstdint>
#include <span>

#include "refine/boundary_planes.hpp"
#include "surface/sampler.hpp"

namespace isopatch::refine {

enum class Landing : std::uint8_t {
  Ok,          ///< on f = 0 within the tolerance
  Stalled,     ///< no convergence in the allowed steps, or a vanishing (in-plane) gradient
  TooFar,      ///< moved further from its start than allowed: possibly onto another sheet
  TurnedAway,  ///< the normal where it landed turns away from the expected one: a fold
};

/// One point to put on f = 0.
struct NewtonPoint {
  Vec3 position = Vec3::Zero();         ///< in: the start; out: where it landed (the last iterate if not Ok)
  Vec3 expected_normal = Vec3::Zero();  ///< unit normal the landing must agree with (dot > min_normal_dot);
                                        ///< zero: no check
  Vec3 normal = Vec3::Zero();           ///< out: unit grad f where it landed
  double max_move = 0;                  ///< largest allowed distance from the start (> 0)
  int plane = -1;                       ///< a cut plane of `planes` to stay on, or -1
  std::uint32_t piece = 0;              ///< the function to land on (an index into `functions`)
  Landing landing = Landing::Ok;
};

struct NewtonLimits {
  double tolerance = 0.0;       ///< |f| / |grad f (in plane)| at which a point has landed
  int max_steps = 12;           ///< Newton steps at most
  double min_normal_dot = 0.5;  ///< landing normal against the expected one (cos 60 degrees)
};

/// out[i] = the value and gradient at at[i] of functions[piece[i]] (piece empty: of functions[0]), one
/// batch per function. \pre out.size() == at.size(); piece empty or as long, every entry < functions.size().
/// \throw EvaluationError if a value or gradient is not finite.
void value_gradients(std::span<const Sampler* const> functions, std::span<const Vec3> at,
                     std::span<const std::uint32_t> piece, std::span<ValueGradient> out);

/// Lands every point of `points` (each independently; see the file comment) on functions[point.piece].
/// \pre every point's piece < functions.size(); no function is null.
/// \throw EvaluationError if f or grad f is not finite at an iterate.
void land_on_surface(std::span<const Sampler* const> functions, const BoundaryPlanes& planes,
                     std::span<NewtonPoint> points, const NewtonLimits& limits);

/// The same on one function (every point's piece is ignored).
void land_on_surface(const Sampler& f, const BoundaryPlanes& planes, std::span<NewtonPoint> points,
                     const NewtonLimits& limits);

}  // namespace isopatch::refine
