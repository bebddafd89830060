#pragma once
/// \file patch_relaxation.hpp
/// The clean-up of one projected patch with its boundary held: the surface-bound remeshing of
/// remesh.hpp (Botsch & Kobbelt 2004 restricted to f = 0: split, collapse, valence flips, tangential
/// relaxation, every moved vertex projected back onto the patch's own function) run on the patch
/// alone. Its boundary vertices are the shared curve samples; the remesher never moves or removes a
/// vertex on a mesh boundary, so they stay shared with the neighbouring patches exactly.

#include <isopatch/mesh_stats.hpp>
#include <isopatch/remesh.hpp>
#include <isopatch/surface.hpp>

#include <vector>

#include "composite_mesher/composite_patch.hpp"

namespace isopatch {

/// Remeshes `piece` (ids as in PatchPiece; boundary ids index `positions`) on `surface` with its
/// boundary fixed and returns it in the same form: the boundary ids it used, new interior vertices.
/// \throw what remesh_on_surface() throws; Error(Internal) if a boundary vertex did not survive.
PatchPiece relax_patch(const PatchPiece& piece, const std::vector<Vec3>& positions, const Surface& surface,
                       const RemeshSettings& settings, RemeshStats& stats);

}  // namespace isopatch
