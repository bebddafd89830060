#pragma once
/// \file singular_points.hpp
/// Singular points of f = 0: the points of a box where f = 0 and grad f = 0 (cone apexes, cusps such as
/// the heart's, the nodes of the Barth surfaces, tangent sheets) and the curves where two sheets cross
/// (a Klein bottle's self-intersection), found by interval subdivision and Gauss-Newton
/// (docs/algorithms.md 1.2.1).
///
/// The method follows the interval solvers of Snyder (1992, "Interval analysis for computer graphics",
/// SIGGRAPH, sec. 4: exclude boxes by an inclusion function, subdivide the rest, refine the solutions
/// by Newton) as Stander and Hart (1997, "Guaranteeing the topology of an implicit surface
/// polygonization for interactive modeling", SIGGRAPH) use it for the critical points of f. A box is
/// dropped when an enclosure of f or of a component of grad f excludes 0: the surface's own enclosure
/// (Surface::gradient_bound) and, where the surface bounds its Hessian (Surface::hessian_bound), the
/// centred (mean value) forms, which shrink with the square of the box; a box where Krawczyk's operator
/// for grad f = 0 proves exactly one critical point is not split further. The rest are halved on their
/// longest side down to a given size. Gauss-Newton on the four equations f = f_x = f_y = f_z = 0
/// (Jacobian rows grad f and the Hessian, a truncated pseudo-inverse, so it also converges onto a
/// curve of solutions and, linearly, into cusps) refines each remaining box's centre.

#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace isopatch {

/// How far the search went.
enum class SingularSearchStatus {
  Complete,         ///< every box was excluded or refined to the smallest size: nothing was left out
  BudgetExhausted,  ///< max_boxes or max_starts stopped it: what was found is listed, more may exist
  NotSearched,      ///< the surface has no interval bounds (a C++ callable, a composite): not searched
};

/// "complete", "budget exhausted" or "not searched".
const char* status_name(SingularSearchStatus status);

/// The limits of the search. Zeros stand for the defaults stated.
struct SingularSearchSettings {
  /// Boxes whose longest side is at most this are not split further: each is a start of Gauss-Newton.
  /// 0: the box's longest side / 256 (a quarter of the default edge length).
  double min_box_size = 0.0;
  /// Converged points closer than this are one; a curve is sampled at about this spacing.
  /// 0: min_box_size.
  double spacing = 0.0;
  /// Interval enclosures evaluated at most (the subdivision's budget; its time is bounded by it).
  std::size_t max_boxes = 1000000;
  /// Gauss-Newton runs at most; beyond that the starts are thinned evenly and the search is incomplete.
  std::size_t max_starts = 100000;
  /// Accepted when |grad f| <= tolerance * G and |f| <= tolerance * G * w at the converged point, with
  /// w the start box's longest side and G the largest |grad f| at the corners of the start box (the
  /// scale of grad f there, so the test does not change when f or the coordinates are scaled).
  double tolerance = 1e-6;
  /// When set, only converged points for which it returns true are listed (a region inside the box, a
  /// rotated box); called from the calling thread only.
  std::function<bool(const Vec3&)> inside;
};

/// A connected group of points where f = 0 and grad f = 0: an isolated point, or samples along a curve.
struct SingularComponent {
  bool curve = false;  ///< true when it holds two or more samples (a curve or a small patch)
  /// True when f = 0 is one smooth sheet there and only f is degenerate (grad f vanishes across the
  /// sheet, as along the heart's equator, where f = (u - c^(1/3) z)(u^2 + ...)): not a singular point
  /// of the surface, though Newton converges slowly and f's curvature formulas lose digits there.
  bool smooth_sheet = false;
  Vec3 position = Vec3::Zero();  ///< the point, or the curve's sample with the smallest residual
  Box extent;                    ///< bounds of the samples (lo = hi for an isolated point)
  std::size_t samples = 0;       ///< points of SingularPoints::points in this component
};

/// What find_singular_points found.
struct SingularPoints {
  SingularSearchStatus status = SingularSearchStatus::NotSearched;
  std::string reason;  ///< why it is not complete (empty when Complete)
  /// Every point found, at least `spacing` apart, component by component (each component's samples
  /// consecutive, sorted by position, in the order of `components`).
  std::vector<Vec3> points;
  /// The singular components (smooth_sheet false) first, then the smooth-sheet ones; each group
  /// sorted by position (x, then y, then z).
  std::vector<SingularComponent> components;
  double min_box_size = 0.0;  ///< the resolved settings
  double spacing = 0.0;
  std::size_t boxes = 0;      ///< interval enclosures evaluated
  std::size_t starts = 0;     ///< Gauss-Newton runs
  std::size_t converged = 0;  ///< runs accepted (before merging)

  bool searched() const { return status != SingularSearchStatus::NotSearched; }
  /// Singular components (smooth_sheet false) that are isolated points, and that are curves.
  std::size_t isolated_points() const;
  std::size_t curves() const;
  /// Components where f = 0 is a smooth sheet (smooth_sheet true).
  std::size_t degenerate() const;
  /// The samples of the singular components (smooth_sheet false): where the surface is singular.
  std::vector<Vec3> singular_samples() const;
};

/// Finds the points of `box` where f = 0 and grad f = 0 (see the file comment for the method).
///
/// Takes a surface with sound enclosures (Surface::gradient_bound; Surface::hessian_bound makes the
/// search much faster but is optional); a surface whose enclosure over `box` is nullopt is not
/// searched (status NotSearched and a reason: never a silent "none"). Sub-boxes whose enclosure is
/// nullopt or unbounded are kept (never excluded without proof); an empty enclosure (f NaN on the
/// whole box) is excluded.
///
/// Guarantees: with status Complete, every point of `box` where f = 0 and grad f = 0 lies in a box that
/// was refined by Gauss-Newton (none was excluded): one of the smallest boxes, or a larger one holding
/// exactly one zero of grad f (Krawczyk); a point is listed when that run converged to it
/// (within one start box of the start box, and in `box` up to 1e-9 of its diagonal) with the residuals
/// of `tolerance`. Converged points closer than `spacing` are merged (the one with the smaller residual
/// kept); each is classified by the sign of f on the sphere of radius `spacing` about it (a smooth
/// sheet when it is that of a half-space, SingularComponent::smooth_sheet), and points of one kind
/// closer than 3 spacings form one component. The subdivision goes level by level, each level's boxes,
/// the runs and the classifications evaluated in parallel (oneTBB, in the caller's task arena) into
/// their own slots, so the result is the same for any number of threads. Time: at most max_boxes
/// enclosures (each one or two of Surface::gradient_bound and Surface::hessian_bound) and max_starts runs
/// of at most 60 Gauss-Newton steps (one second-order evaluation each and up to 8 more when a step must
/// be shortened, plus 8 gradients per run), and 256 values of f per merged point. Measured at the
/// default settings in docs/algorithms.md 1.2.1 (the regular catalogue surfaces: 1 to 14000 boxes).
/// Exceptions from the surface (e.g. a LimitError of a budgeted surface) pass through; non-finite
/// values only drop the run where they occur.
///
/// \throw InputError when `box` is not valid() (setting "box")
/// \throw SettingError for a negative or non-finite min_box_size or spacing, max_boxes or max_starts 0,
///        or a tolerance outside (0, 1) (setting named by its field)
SingularPoints find_singular_points(const Surface& surface, const Box& box,
                                    const SingularSearchSettings& settings = {});

/// A point as "(x, y, z)" with 4 significant digits, coordinates smaller than `zero` shown as 0.
std::string format_singular_point(const Vec3& p, double zero);

/// What was found, in one line for warnings and reports, naming the singular components only:
/// "2 singular points of f = 0 (grad f = 0) in the box: (0, 0, -1), (0, 0, 1)"; curves as
/// "a curve of 412 samples within (-1, -1, -0.5) .. (1, 1, 0.5)"; at most `listed` components named,
/// then "and N more"; "(the search stopped at its budget: there may be more)" when it did. Empty when
/// no singular component was found.
std::string describe_singular_points(const SingularPoints& found, const Box& box, std::size_t listed = 8);

/// The same for the smooth-sheet components: "grad f also vanishes where f = 0 is a smooth sheet (f is
/// degenerate there, the surface is not): a curve of 262 samples within ..."; empty when there is none.
std::string describe_degenerate_points(const SingularPoints& found, const Box& box, std::size_t listed = 8);

}  // namespace isopatch
