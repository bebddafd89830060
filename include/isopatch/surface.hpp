#pragma once
/// \file surface.hpp
/// The Surface a mesher sees: the zero set of a scalar function f(x, y, z) with f < 0 inside, together
/// with exact first and second derivatives and, when available, interval bounds over a box.
///
/// Surfaces are immutable and shared: pass `const Surface&` to algorithms, hold `SurfacePtr`.
/// Every method is safe to call concurrently from several threads. The result types of the
/// derivatives (ValueGradient, SecondOrder, IntervalGradient) are in derivatives.hpp.

#include <isopatch/derivatives.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/interval.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace isopatch {

class Expression;

class Surface {
 public:
  /// \param name  shown in summaries and errors
  /// \param box   the default bounding box used when the caller gives none (must be valid())
  Surface(std::string name, Box box) : name_(std::move(name)), box_(box) {}
  virtual ~Surface() = default;
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  /// f(p). May return NaN or infinity: callers check (see EvaluationError).
  virtual double value(const Vec3& p) const = 0;
  /// Batch evaluation: out[i] = f(points[i]). \pre out.size() == points.size().
  virtual void values(std::span<const Vec3> points, std::span<double> out) const;
  /// f(p) and its exact gradient.
  virtual ValueGradient value_gradient(const Vec3& p) const = 0;
  /// Batch evaluation of value and gradient together: out[i] = value_gradient(points[i]), the same
  /// numbers bit for bit (the default loops; a surface may evaluate the batch at once).
  /// \pre out.size() == points.size().
  virtual void value_gradients(std::span<const Vec3> points, std::span<ValueGradient> out) const;
  /// f(p), gradient and Hessian (exact, forward-mode differentiation).
  virtual SecondOrder second_order(const Vec3& p) const = 0;
  /// A sound enclosure of f over `box` (every f(p), p in box, lies in it), or nullopt when this
  /// surface cannot bound itself (e.g. an opaque C++ callable).
  virtual std::optional<Interval> bound(const Box& box) const;
  /// Sound enclosures of f and of its gradient over `box`, or nullopt.
  virtual std::optional<IntervalGradient> gradient_bound(const Box& box) const;
  /// Sound enclosures of f, its gradient and its Hessian over `box`, or nullopt (the default: only the
  /// singular-point search uses them, singular_points.hpp).
  virtual std::optional<IntervalHessian> hessian_bound(const Box& box) const;

  /// The compiled formula behind this surface, or nullptr (callables, volumes, wrappers): what the
  /// crease analysis of CSG shapes reads (src/csg).
  virtual const Expression* expression() const { return nullptr; }

  const std::string& name() const { return name_; }
  const Box& box() const { return box_; }

 private:
  std::string name_;
  Box box_;
};

using SurfacePtr = std::shared_ptr<const Surface>;

}  // namespace isopatch
