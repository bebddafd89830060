#pragma once
/// \file face_set.hpp
/// The faces of a CSG shape read from its expression: every min, max and abs fixed to the branch taken
/// at a point gives that point's face function (expr/branches.hpp); faces that meet without a crease
/// (the two sides of a smooth union's blend, where the branches' gradients agree) are merged into one
/// face whose function leaves the switches they differ in open (smooth there). docs/creases.md.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace isopatch {

class Expression;

/// The faces of f = 0 seen so far, by branch choice, with their functions. Not thread-safe while faces
/// are added (face_at()); the functions it hands out are.
class FaceSet {
 public:
  /// \param f    the whole function (its tape is read)
  /// \param box  the box given to the face functions
  FaceSet(const Expression& f, const Box& box);
  ~FaceSet();
  FaceSet(const FaceSet&) = delete;
  FaceSet& operator=(const FaceSet&) = delete;

  /// Whether f has a min, max or abs at all (else it has one face and no crease).
  bool has_switches() const;
  /// The face whose branches f takes at p (a new face when they were not seen before), as its merged
  /// face: faces merged by merge() answer with the same id, the smallest of them.
  int face_at(const Vec3& p);
  /// Whether a point of fi = 0 lies on f = 0 (|f| <= tolerance |grad fi| there).
  bool on_shape(const Vec3& p, const Surface& fi, double tolerance) const;
  /// -1 when f takes the branches of each of `faces` at p (ties within `tolerance` count: p lies in
  /// every one's region; a merged face holds where one of its members does); else the face across the
  /// first one's region boundary at p: its branches with the first one f does not take switched over,
  /// the rest as f takes them there (possibly a new face). One run of f's tape.
  int boundary_face(std::span<const int> faces, const Vec3& p, double tolerance);
  /// For each switch s of `switches`, the two (merged) faces on either side of it at p: the branches f
  /// takes at p with switch s taken one way and the other, the dead switches left open (either may be a
  /// new face). One run of f's tape for all of them.
  /// \pre each s in 0 .. the number of switches of expression().tape() (expr::switch_instructions()).
  std::vector<std::pair<int, int>> faces_across(std::span<const int> switches, const Vec3& p);
  /// Merges two faces that meet without a crease. \pre both ids came from face_at().
  void merge(int a, int b);
  /// The merged face of a face id (the smallest id merged with it).
  int root(int face) const;
  /// The function of a (merged) face: f with the branches its members share fixed. Built on first use;
  /// merging afterwards is not allowed (\throw Error of kind Internal).
  const SurfacePtr& function(int face);
  /// The function of one face id on its own (its branches fixed, merged or not).
  const SurfacePtr& fine_function(int face);
  /// A bound of the face's region for the projection (composite.hpp bounds): -|f - f_face|, zero where
  /// f takes the face's branches and, to first order, minus the distance to that region elsewhere.
  SurfacePtr region_bound(int face);
  /// The expression of f.
  const Expression& expression() const;
  /// The whole function f as a surface.
  const SurfacePtr& whole() const { return whole_; }
  /// Number of face ids handed out (merged ones included).
  std::size_t size() const { return choices_.size(); }

 private:
  struct Tapes;
  std::unique_ptr<Tapes> tapes_;
  Box box_;
  SurfacePtr whole_;
  std::vector<std::vector<std::int8_t>> choices_;
  std::vector<int> parent_;
  std::vector<SurfacePtr> functions_;
  std::vector<SurfacePtr> fine_;
  std::vector<SurfacePtr> bounds_;

  /// The (merged) face of a branch choice, registered when new.
  int id_of(std::vector<std::int8_t> choice);
};

/// A point put on two face functions to a Newton tolerance t is on f = 0 when |f| <= this many t
/// (FaceSet::on_shape): the tracers' test of a point still on the shape.
inline constexpr double kOnShapeTolerances = 1e3;

/// The plane n . x = d as a surface (n unit): the seams that cut a face into disc-like pieces.
SurfacePtr plane_surface(const Vec3& normal, double offset, const Box& box);

}  // namespace isopatch
