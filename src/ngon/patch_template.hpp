#pragma once
/// \file patch_template.hpp
/// Template triangulations of the n-gon domain at resolution r (segments per side), the fixed
/// connectivity that every n-sided patch of the projection mesher is sampled with (Sipos & Salvi,
/// "Creating good quality meshes from smooth implicit surfaces", WAIT 2021, section 2.2; the ring
/// layouts follow the concentric-ring triangulation described there). Three layouts:
///   - n = 3: barycentric triangle grid,  V = (r+1)(r+2)/2,    T = r^2;
///   - n = 4: structured grid, one diagonal direction everywhere,  V = (r+1)^2,  T = 2 r^2;
///   - n >= 5: concentric rings around a centre vertex,  V = 1 + n r(r+1)/2,  T = n r^2.
/// Indexing follows the convention of domain.hpp (corner k at V_k, side k from V_k to V_{k+1}). Every
/// side carries exactly r segments, its vertices at t = i/r placed with Domain::side_point(), so
/// neighbouring patches can share boundary vertices by (side, i).
/// Every triangle is similar to one of the coarsest layout (the ring layout is the uniform lattice
/// subdivision of the fan triangles (centre, V_k, V_{k+1})), so the smallest angle in the domain is
/// independent of r: 60 deg (n = 3), 45 (n = 4), min(360/n, 90 - 180/n) for n >= 5, i.e. 30 at n = 12.

#include <isopatch/stage_settings.hpp>
#include "ngon/barycentric.hpp"
#include "ngon/domain.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace isopatch {

/// Where a template vertex sits on the domain boundary.
struct VertexTag {
  enum class Kind : std::uint8_t { Corner, Side, Interior };
  Kind kind = Kind::Interior;
  int side = -1;  ///< Corner: the corner index k (at V_k); Side: the side index k; Interior: -1
  int index = 0;  ///< Side: i in 1..r-1, the vertex is at t = i/r from V_k; otherwise 0
};

using TemplateTriangle = std::array<int, 3>;  ///< vertex indices, counter-clockwise in the domain

/// An immutable template triangulation. Build it with patch_template() (cached) or the constructor.
class PatchTemplate {
 public:
  static constexpr int kMinResolution = 1;
  static constexpr int kMaxResolution = kMaxPatchResolution;

  /// \throw InputError unless 3 <= n <= 12 and 1 <= r <= 64.
  PatchTemplate(int n, int r, CoordinateKind kind);

  int sides() const { return domain_.sides(); }
  int resolution() const { return r_; }
  CoordinateKind coordinates() const { return kind_; }
  const Domain& domain() const { return domain_; }

  std::size_t vertex_count() const { return points_.size(); }
  std::size_t triangle_count() const { return triangles_.size(); }
  std::span<const Vec2> points() const { return points_; }
  std::span<const VertexTag> tags() const { return tags_; }
  std::span<const TemplateTriangle> triangles() const { return triangles_; }
  /// All coordinates, n per vertex: lambda(v)[k] == lambdas()[v * n + k].
  std::span<const double> lambdas() const { return lambdas_; }

  const Vec2& point(int v) const { return points_[static_cast<std::size_t>(v)]; }
  const VertexTag& tag(int v) const { return tags_[static_cast<std::size_t>(v)]; }
  /// lambda_0 .. lambda_{n-1} at vertex v. On the boundary they are set from the tag, exactly:
  /// e_k at corner k; 1 - i/r and i/r at positions k and k+1 on side k, 0 elsewhere.
  std::span<const double> lambda(int v) const;
  /// The r + 1 vertices of side k (taken mod n), from corner k to corner k + 1 inclusive: entry i is at
  /// t = i/r.
  std::span<const int> side_vertices(int k) const;
  /// The index of corner k (taken mod n), i.e. side_vertices(k)[0].
  int corner(int k) const { return side_vertices(k)[0]; }
  /// The centre vertex of a ring template (n >= 5), at the origin; -1 for n = 3 and n = 4.
  int centre() const { return centre_; }

 private:
  Domain domain_;
  int r_;
  CoordinateKind kind_;
  int centre_ = -1;
  std::vector<Vec2> points_;
  std::vector<VertexTag> tags_;
  std::vector<TemplateTriangle> triangles_;
  std::vector<double> lambdas_;
  std::vector<int> side_vertices_;  // n blocks of r + 1
};

/// The template for (n, r, kind), built on first use and shared afterwards. Thread-safe.
/// \throw InputError unless 3 <= n <= 12 and 1 <= r <= 64.
std::shared_ptr<const PatchTemplate> patch_template(int n, int r, CoordinateKind kind);

}  // namespace isopatch
