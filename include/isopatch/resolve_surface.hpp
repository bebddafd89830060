#pragma once
/// \file resolve_surface.hpp
/// Surfaces from text: a formula of the expression language (expression.hpp), a catalogue name
/// (catalogue.hpp) or a formula file, as the command line takes them.

#include <isopatch/convex_region.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/surface.hpp>

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace isopatch {

class Expression;

/// The surface f = 0 of a formula, with every Surface service: batch values, exact gradients and
/// Hessians (forward mode), sound interval bounds of f and of its gradient.
/// \param formula the formula text (definitions, `;` or new lines, `#` comments; README.md)
/// \param box     its default box (must be valid())
/// \param name    shown in summaries; when empty, the formula on one line (shortened to 60 characters)
/// \param params  values overriding the formula's definitions (`--param r=0.3`)
/// \throw ParseError for a malformed formula
/// \throw InputError for an invalid box or a parameter that names no definition
SurfacePtr expression_surface(const std::string& formula, const Box& box, std::string name = {},
                              const std::map<std::string, double>& params = {});

/// The surface f = 0 of an already compiled expression (the same services as above).
/// \throw InputError for an invalid box.
SurfacePtr expression_surface(Expression expression, const Box& box, std::string name);

/// The catalogue surface of that name, compiled from its formula, with its default box.
/// \throw UnknownSurfaceError naming the closest entry: "unknown surface 'tours' (did you mean 'torus'?)"
/// \throw InputError for a parameter that names no definition of the formula
SurfacePtr catalogue_surface(std::string_view name, const std::map<std::string, double>& params = {});

/// What the command line's surface argument means. The rule:
///  - `@path`: the formula in that file (an IoError when it cannot be read);
///  - a single identifier ([A-Za-z_][A-Za-z0-9_]*): a catalogue name when the catalogue has it, a
///    formula when it is one on its own (x, y, z, pi, e), else an UnknownSurfaceError suggesting the
///    closest name (a bare identifier is never a useful surface);
///  - anything else: a formula.
/// A formula needs `box` (else InputError "a formula needs a box", setting "box"); a catalogue surface uses
/// its own box unless `box` is given. \throw UnknownSurfaceError, ParseError, IoError, InputError as above
SurfacePtr resolve_surface(const std::string& spec, const std::optional<Box>& box,
                           const std::map<std::string, double>& params = {});

/// resolve_surface() for a mesh inside `region` (Settings::region): without `box`, a formula takes the
/// bounds of a bounded region as its box (region_bounds(), convex_region.hpp); a catalogue surface keeps
/// its own box (an unbounded region lies inside it). With `box`, or an empty region, resolve_surface().
/// \throw SettingError("region") for a formula without a box in an unbounded region (a formula has no
///        box of its own) or a bad plane; otherwise as resolve_surface().
SurfacePtr resolve_surface_in_region(const std::string& spec, const std::optional<Box>& box,
                                     const ConvexRegion& region,
                                     const std::map<std::string, double>& params = {});

}  // namespace isopatch
