#pragma once
/// \file error.hpp
/// The one error policy of isopatch: every failure caused by input throws a typed error derived from
/// isopatch::Error (itself a std::runtime_error) carrying a one-line message in the library's own terms
/// (what went wrong) and, where one setting is to blame, that setting's name (where: the Settings field,
/// e.g. "max_vertices"). Front ends map both to their own words: the command-line tool maps ErrorKind
/// to a distinct exit code and setting names to its flags.

#include <stdexcept>
#include <string>
#include <utility>

namespace isopatch {

/// What kind of input was bad; each kind has its own exit code in the command-line tool.
enum class ErrorKind {
  Internal,         ///< a bug: an invariant did not hold
  InvalidArgument,  ///< a setting out of range (absurd resolution, bad box, ...)
  UnknownSurface,   ///< a surface name that is not in the catalogue
  Parse,            ///< a malformed formula
  Io,               ///< a file that cannot be read or written, or a malformed mesh file
  Evaluation,       ///< f returned NaN or infinity where it was evaluated
  NoSurface,        ///< f = 0 does not cross the box
  Limit,            ///< a resource budget (evaluations, time, vertices) was exhausted or cancelled
  SingularSurface,  ///< grad f vanishes on f = 0 (a repeated factor, f = g^3): no gradient to mesh with
  Crease,           ///< a CSG shape whose faces meet in a way that cannot be meshed (non-manifold, lost)
};

/// Base of all isopatch errors.
class Error : public std::runtime_error {
 public:
  /// \param kind     what kind of failure it is (the tool maps each kind to an exit code)
  /// \param message  one line, returned by what()
  /// \param setting  the Settings field (or argument) the error is about, empty when none is
  Error(ErrorKind kind, const std::string& message, std::string setting = {})
      : std::runtime_error(message), kind_(kind), setting_(std::move(setting)) {}
  ErrorKind kind() const noexcept { return kind_; }
  /// The name of the Settings field (or argument: "box", "params", ...) the error is about; empty
  /// when it concerns no single setting.
  const std::string& setting() const noexcept { return setting_; }

 private:
  ErrorKind kind_;
  std::string setting_;
};

/// A setting or argument out of its documented range.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message, std::string setting = {})
      : Error(ErrorKind::InvalidArgument, message, std::move(setting)) {}
};

/// A Settings field out of its documented range: setting() names it.
class SettingError : public InputError {
 public:
  SettingError(std::string setting, const std::string& message) : InputError(message, std::move(setting)) {}
};

/// A surface name that names nothing.
class UnknownSurfaceError : public Error {
 public:
  explicit UnknownSurfaceError(const std::string& message) : Error(ErrorKind::UnknownSurface, message) {}
};

/// A file that cannot be opened, read, parsed or written. The message names the file.
class IoError : public Error {
 public:
  explicit IoError(const std::string& message) : Error(ErrorKind::Io, message) {}
};

/// f (or its gradient) was NaN or infinite at a point the mesher needed.
class EvaluationError : public Error {
 public:
  explicit EvaluationError(const std::string& message) : Error(ErrorKind::Evaluation, message) {}
};

/// The surface does not cross the box at all.
class NoSurfaceError : public Error {
 public:
  explicit NoSurfaceError(const std::string& message) : Error(ErrorKind::NoSurface, message) {}
};

/// grad f vanishes on (much of) f = 0, so neither projection nor curvature can use it.
class SingularSurfaceError : public Error {
 public:
  explicit SingularSurfaceError(const std::string& message) : Error(ErrorKind::SingularSurface, message) {}
};

/// The faces of a CSG shape meet in a way no mesh can follow: two solids touching along an edge or at a
/// point (not a 2-manifold), a sheet of zero thickness, a crease the tracer cannot follow.
class CreaseError : public Error {
 public:
  explicit CreaseError(const std::string& message) : Error(ErrorKind::Crease, message) {}
};

/// A CSG shape that is not a 2-manifold where its faces meet (solids touching along an edge or at a
/// point, faces touching without crossing): no mesh can follow it, so it is refused whatever
/// Settings::creases asks (a CreaseError, exit code 11; Python's isopatch.CreaseError).
class ShapeNotManifoldError : public CreaseError {
 public:
  explicit ShapeNotManifoldError(const std::string& message) : CreaseError(message) {}
};

/// A budget ran out or the run was cancelled; setting() names the budget ("max_evaluations",
/// "time_limit", "max_vertices", "cancel").
class LimitError : public Error {
 public:
  explicit LimitError(const std::string& message, std::string setting = {})
      : Error(ErrorKind::Limit, message, std::move(setting)) {}
};

}  // namespace isopatch
