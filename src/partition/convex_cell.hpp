#pragma once
/// \file convex_cell.hpp
/// A convex polyhedron made of planar cuts (Sipos & Salvi 2021, sec. 2: the method "can be used with
/// any convex partitioning which is made of planar cuts"): vertices, polygonal faces (counter-clockwise
/// seen from outside) and the plane of every face. Built by clipping a box by half-spaces one at a
/// time. Robust to nearly parallel and nearly coincident planes: a point within the tolerance of a
/// plane counts as on it, so a plane that removes no vertex by more than the tolerance is redundant
/// and leaves the cell as it was (the first of two nearly coincident planes bounds the cell).

#include <isopatch/geometry.hpp>

#include <cstdint>
#include <vector>

namespace isopatch {

/// The half-space normal . x + offset <= 0, with a unit normal, and a caller's label (who made it).
struct CellPlane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
  std::int64_t label = -1;

  double distance(const Vec3& p) const { return normal.dot(p) + offset; }
};

/// The plane a x + b y + c z + d <= 0 scaled to a unit normal.
/// \throw InputError when a, b, c, d are not finite or (a, b, c) is zero.
CellPlane make_cell_plane(double a, double b, double c, double d, std::int64_t label = -1);

class ConvexCell {
 public:
  struct Face {
    std::size_t plane = 0;                ///< index into planes()
    std::vector<std::uint32_t> vertices;  ///< counter-clockwise about the plane's (outward) normal
  };

  /// The box as a cell; its six planes (labels -1 .. -6: -x, +x, -y, +y, -z, +z) have exact axis
  /// normals, so its faces are exactly axis-aligned. `tolerance` (> 0) is the distance within which a
  /// point counts as on a plane in later clips.
  /// \throw InputError for an invalid box.
  static ConvexCell box(const Box& box, double tolerance);

  /// Cuts away the part beyond `plane`. False when nothing of positive volume is left (the cell is
  /// then empty()). A plane that no vertex lies beyond by more than the tolerance leaves the cell
  /// unchanged (and is not added).
  bool clip(const CellPlane& plane);

  bool empty() const { return faces_.empty(); }
  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<CellPlane>& planes() const { return planes_; }
  double tolerance() const { return tolerance_; }

  double volume() const;
  Vec3 centroid() const;  ///< of the volume
  Box bounds() const;
  /// Whether p lies inside every face plane, or beyond one by at most `margin`.
  bool contains(const Vec3& p, double margin) const;

 private:
  std::vector<Vec3> vertices_;
  std::vector<Face> faces_;
  std::vector<CellPlane> planes_;
  double tolerance_ = 0.0;
};

/// The cell { x in `bounds` : every plane's half-space }, the planes applied in order.
/// \throw InputError ("... is empty") when the intersection has no volume above
///        min_volume_fraction of the box's volume.
ConvexCell intersect_half_spaces(const Box& bounds, const std::vector<CellPlane>& planes,
                                 double min_volume_fraction = 1e-12);

/// The distance below which points count as on a plane for cells of size `scale` at coordinates up to
/// `magnitude`: 1e-12 of the scale, or 64 ulps of the coordinates where that is larger.
double cell_tolerance(double scale, double magnitude);

}  // namespace isopatch
