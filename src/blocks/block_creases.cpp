// A formula with exact creases meshed as blocks (blocks.hpp): its crease analysis made once per process
// (api/crease_meshing.hpp, as one process makes it), its pieces meshed and refined as a composite's
// (block_composite.cpp), then the crease angle repair of one process with the block's seams held.
#include <isopatch/blocks.hpp>
#include <isopatch/composite_mesh.hpp>

#include <isopatch/error.hpp>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "api/crease_meshing.hpp"
#include "blocks/block_piece.hpp"
#include "composite_model/composite.hpp"

namespace isopatch {

struct CreasedPieces {
  CompositeModel model;
  std::vector<SurfacePtr> faces;  ///< the shape's face functions (the repair keeps vertices on them)
  Box box;                        ///< the box the analysis was made in (the repair's tolerances)
};

namespace {

/// What meshes a shape the blocked run's crease path refuses: one process's other crease paths, or
/// turning creases off.
constexpr const char* kBlockedRemedy =
    "; blocks (--tiles) follow creases only by cutting each face into pieces by planes, which fails on faces "
    "of many handles: one process (without --tiles) meshes lattices capped, cut, with inserts, voids or "
    "skins along their creases (docs/lattices.md); turning creases off (--creases off) meshes it as a "
    "smooth surface (creases rounded)";

}  // namespace

std::shared_ptr<const CreasedPieces> creased_pieces(const Surface& surface, const Settings& settings) {
  settings.validate();
  std::optional<CsgShape> shape;
  try {
    shape = analyse_creases(surface, settings);
  } catch (const ShapeNotManifoldError& e) {
    throw ShapeNotManifoldError(std::string(e.what()) + kBlockedRemedy);
  } catch (const CreaseError& e) {
    throw CreaseError(std::string(e.what()) + kBlockedRemedy);
  }
  if (!shape) return nullptr;
  return std::make_shared<const CreasedPieces>(
      CreasedPieces{CompositeModel(std::make_shared<const Composite>(std::move(shape->composite))),
                    std::move(shape->face_functions), settings.box.value_or(surface.box())});
}

BlockBase block_base(const CreasedPieces& pieces, const Settings& settings) {
  settings.validate();
  return blocks::composite_block_base(pieces.model, settings);
}

BlockMesh refine_block(const CreasedPieces& pieces, const BasePatches& patches, const Settings& settings,
                       const Mesh& base, const BlockPlan& plan, int block) {
  return blocks::refine_composite_block(pieces.model, patches, settings, base, plan, block,
                                        [&](Mesh& refined, const std::vector<std::uint8_t>& held) {
                                          repair_crease_angles(refined, pieces.faces, pieces.box, &held);
                                        });
}

}  // namespace isopatch
