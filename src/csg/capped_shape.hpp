#pragma once
// A smooth solid capped by a convex polyhedron, read from its formula: f = max(g, p_1, ..., p_k) with
// every p_i affine (a plane) and g the one operand that is not. That is how lattice parts are written
// (a gyroid capped by its box: max(gyroid, max(max(abs(x), abs(y)), abs(z)) - a)), and such a shape is
// meshed as g = 0 cut open by the polyhedron, closed by planar caps (api/capped_meshing.hpp), which
// needs no cut of g's face into discs, whatever its genus (docs/lattices.md).

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <optional>

namespace isopatch {

/// f split into the smooth operand and the caps' planes.
struct CappedShape {
  SurfacePtr smooth;    ///< g: f where the planes do not decide it (a formula of its own); null for a
                        ///< polyhedron (every operand a plane)
  ConvexRegion planes;  ///< unit normals (a, b, c) pointing out of the solid; p_i = n . x + d
};

/// The most planes a capped shape may have (a polyhedron of more faces is meshed the general way).
inline constexpr std::size_t kMaxCapPlanes = 64;

/// Splits `f` when it is max(g, p_1, ..., p_k): a tree of max whose leaves are reached through
/// increasing steps only (adding a constant, multiplying or dividing by a positive one), `abs` of an
/// affine operand counting as the max of it and its negation, with exactly one leaf that is not affine
/// and 1..kMaxCapPlanes affine ones, or with every leaf affine (a polyhedron, `smooth` null). Returns nullopt
/// for any other formula (nothing is evaluated but the planes' coefficients; `f` without an expression gives
/// nullopt). Duplicate planes are kept once. g is a formula surface over `box`.
std::optional<CappedShape> split_capped_shape(const Surface& f, const Box& box);

/// Two smooth solids intersected: f = max(a, b) through increasing steps, neither operand with a plane
/// under it (a lattice cut by a sphere: max(gyroid, x^2 + y^2 + z^2 - r^2)). Meshed as a = 0 trimmed where
/// b < 0 and b = 0 trimmed where a < 0, joined along their crease (api/curved_cut.hpp). Or two smooth
/// solids united, f = min(a, b) (a lattice with a solid ball in it), read as -max(-a, -b): the same faces
/// and crease, the mesh of max(-a, -b) turned inside out.
struct CutShape {
  SurfacePtr first, second;  ///< a and b in the formula's order (formulas of their own over the box); -a
                             ///< and -b when `united`
  bool united = false;       ///< f = -max(first, second) = min(a, b)
};

/// Splits `f` when it is max(a, b) as above (exactly two leaves of f's tree of max, both not affine), or
/// min(a, b) (the same of -f's tree, a min under a negation split as a max; `united`); nullopt for any
/// other formula (nothing is evaluated; `f` without an expression gives nullopt).
std::optional<CutShape> split_cut_shape(const Surface& f, const Box& box);

/// Two smooth solids capped by planes: f = max(a, b, p_1, ..., p_k) as split_capped_shape() reads it but
/// with exactly two curved leaves (a lattice inside a cylinder capped at both ends:
/// max(gyroid, x^2 + y^2 - r^2, abs(z) - h)).
struct CappedCutShape {
  CutShape solids;      ///< a and b, in the formula's order
  ConvexRegion planes;  ///< unit normals out of the solid; p_i = n . x + d
};

/// Splits `f` when it is such a shape; nullopt for any other formula (nothing is evaluated but the
/// planes' coefficients).
std::optional<CappedCutShape> split_capped_cut_shape(const Surface& f, const Box& box);

/// -f as a formula of its own over `box` when f's root, through increasing steps, is a min: a union,
/// whose complement -f is an intersection and may be a capped shape above (min(g, -P), a lattice united
/// with the outside of a polyhedron, is the capped solid max(-g, P) turned over). Null for any other
/// formula or a surface without an expression. Nothing is evaluated.
SurfacePtr union_complement(const Surface& f, const Box& box);

/// A lattice closed by a skin: f = min(max(g, P), max(P, -R)) (either order, through increasing steps
/// at the root; each operand a capped shape as above): the polyhedron P of the part's planes, solid
/// between it and the inner polyhedron R, the lattice g < 0 inside R ("a lattice shelled by its box").
struct ShelledShape {
  SurfacePtr hollow;   ///< -g: the hollows inside R, where the lattice is not (a formula of its own)
  ConvexRegion outer;  ///< P, unit normals out of the part
  ConvexRegion inner;  ///< R, unit normals out of R
};

/// Splits `f` when it is a shelled lattice (ShelledShape); nullopt for any other formula. The caller
/// checks that R lies inside P.
std::optional<ShelledShape> split_shelled_shape(const Surface& f, const Box& box);

}  // namespace isopatch
