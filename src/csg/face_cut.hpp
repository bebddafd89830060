#pragma once
/// \file face_cut.hpp
/// One cut of a part of a face by a plane (face_regions.hpp): the part's creases split where the plane
/// crosses them, seams traced on the face inside the plane from each crossing to the next
/// (curve_tracer.hpp), closed seams round a part with no crease, and the coarse mesh's part split along
/// the plane. docs/creases.md.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <optional>
#include <set>
#include <vector>

#include "csg/crease_graph.hpp"
#include "csg/crease_search.hpp"
#include "csg/face_cycles.hpp"
#include "csg/face_parts.hpp"
#include "csg/face_set.hpp"

namespace isopatch {

/// What a cut works on: the graph, the faces, the coarse mesh and its parts.
struct PlaneCutter {
  CreaseGraph& graph;
  FaceSet& faces;
  const ShapeSamples& samples;
  Parts& parts;
  double h;          ///< the coarse grid's cell
  double tolerance;  ///< Newton tolerance
  Box box;
  std::set<int> touched;  ///< curves split since it was last cleared

  /// How many curve ends meet at a node.
  int node_degree(int node) const;
  /// The plane through the part's node nearest to it when one lies within a third of a cell (so the
  /// cut runs through that node instead of leaving a curve shorter than that beside it), else as given.
  Plane snapped_to_nodes(Plane plane, const std::vector<const FaceCycle*>& cycles) const;
  /// Appends a seam of face g along `points` on the plane (its ends are the caller's to set).
  GraphCurve& add_seam(const std::vector<Vec3>& points, int g, const SurfacePtr& plane_fn,
                       const Plane& plane);
  /// Inserts the exact point p between dense points k and k + 1 of curve c and splits the curve there.
  int split_at(std::size_t c, std::size_t k, const Vec3& p);
  /// The node at p on a curve of face g: an existing node within a small distance, else the curve of g
  /// nearest to p split there; nullopt when no curve of g passes within a cell.
  std::optional<int> node_on_face_curve(int g, const Vec3& p);
  /// Cuts part `part` of face g (its cycles `cycles`) by `plane`. Returns the seams made (0: the plane
  /// misses the part or only grazes it).
  /// \throw CreaseError when a seam cannot be traced or ends away from the part's creases.
  int cut(int g, int part, const std::vector<const FaceCycle*>& cycles, const Plane& plane);
};

}  // namespace isopatch
