#pragma once
/// \file isopatch.hpp
/// The umbrella header and the one call a user needs: mesh a surface with the method in Settings.

#include <isopatch/callable_surface.hpp>
#include <isopatch/catalogue.hpp>
#include <isopatch/composite_mesh.hpp>
#include <isopatch/error.hpp>
#include <isopatch/fairing.hpp>
#include <isopatch/geometry.hpp>
#include <isopatch/marching_cubes.hpp>
#include <isopatch/mesh.hpp>
#include <isopatch/mesh_io.hpp>
#include <isopatch/projection.hpp>
#include <isopatch/settings.hpp>
#include <isopatch/singular_points.hpp>
#include <isopatch/surface.hpp>

namespace isopatch {

/// Meshes the zero set of `surface` inside settings.box (or surface.box()) with settings.method.
/// The result is an indexed triangle mesh oriented with normals along grad f. Fills `stats` when given.
/// Before meshing, f identically zero on the box (interval bound [0, 0], or f and grad f exactly 0 at
/// a 16^3 grid of samples) is rejected at once with NoSurfaceError ("... f is identically zero ...").
/// \throw InputError, EvaluationError, NoSurfaceError, LimitError (see the method's own header).
Mesh mesh_surface(const Surface& surface, const Settings& settings, MeshStats* stats = nullptr);

/// The singular points of the shape f = 0 in `box` (find_singular_points, singular_points.hpp). For a
/// formula built with min, max or abs (at most 64 operands), those of its smooth operands (f with every
/// switch fixed to a branch) at the points where that operand is the branch f takes (f equal to it
/// there), searched one operand at a time with `settings`: a crease is no point where grad f = 0, but
/// an interval search on f itself cannot exclude the boxes along it (the enclosure of grad max(a, b)
/// there holds both gradients' hull) and subdivides along every crease to its budget. The operands'
/// results are put together (counts added, the status the least complete, components sorted as
/// find_singular_points sorts them). Any other surface: find_singular_points(f, box, settings).
/// 	hrow as find_singular_points.
SingularPoints find_shape_singular_points(const Surface& f, const Box& box,
                                          const SingularSearchSettings& settings = {});

/// "projection" or "mc" -> Method; \throw InputError for anything else.
Method parse_method(const std::string& name);
/// Method -> its command-line name.
std::string method_name(Method method);

}  // namespace isopatch
