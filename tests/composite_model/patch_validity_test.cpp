// The validity check finds the folds beside patch boundaries that make the mesher close a patch by a
// fan (a tapered prism's side through a deep reference point), and nothing on patches that mesh
// cleanly; the constructions' searches for reference points avoid the folds where a candidate does, and
// a setback whose vertex blend region cannot hold its own boundary is refused.
#include <gtest/gtest.h>

#include <isopatch/error.hpp>

#include <string>

#include "composite_model/ipatch_file.hpp"
#include "composite_model/patch_validity.hpp"

namespace isopatch {
namespace {

/// A hexagonal prism with unequal sides whose top is the bottom scaled by `taper`.
std::string hexagonal_prism(double taper) {
  const double base[6][2] = {{1, 0},    {0.6, 1.03923048454},    {-0.45, 0.779422863406},
                             {-1.1, 0}, {-0.5, -0.866025403784}, {0.65, -1.12583302492}};
  std::string text = "ipatch-model 1\n";
  for (double z : {-0.8, 0.8}) {
    const double s = z < 0.0 ? 1.0 : taper;
    for (const auto& p : base)
      text +=
          "v " + std::to_string(s * p[0]) + " " + std::to_string(s * p[1]) + " " + std::to_string(z) + "\n";
  }
  return text +
         "f 6 5 4 3 2 1\nf 7 8 9 10 11 12\nf 1 2 8 7\nf 2 3 9 8\nf 3 4 10 9\nf 4 5 11 10\nf 5 6 12 11\nf 6 1 "
         "7 12\n";
}

const char* kSquarePyramidBlend =
    "ipatch-model 1\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nv 0 0 1\nf 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\n"
    "f 4 1 5\nblend radius 0.12 setback 0.45 facecurve conic\n";

const char* kOctahedronBlend =
    "ipatch-model 1\nv 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\nf 1 3 5\nf 3 2 5\nf 2 4 5\n"
    "f 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\nblend radius 0.1 setback 0.3 facecurve conic\n";

TEST(PatchValidity, FindsTheFoldsOfATaperedPrismsSideThroughADeepReferencePoint) {
  // Face 3 of the prism tapered by 0.8 through a reference point deep inside the solid (the patch dips
  // toward it and folds beside its top and bottom curves), and through one nearer its corners.
  const std::string prism = hexagonal_prism(0.8);
  const Composite deep = parse_ipatch(prism + "face 3 centre 0.312285 0.300139 -0.068947\n", "t.ipatch");
  const BoundaryBend bend = measure_boundary_bend(deep, 2);
  EXPECT_GT(bend.missing, 0);
  bool found = false;
  for (const auto& f : check_patch_validity(deep))
    found |= f.patch == 2 && f.message.find("folds") != std::string::npos;
  EXPECT_TRUE(found);
  const Composite shallow = parse_ipatch(prism + "face 3 centre 0.863858 0.512440 0.034473\n", "t.ipatch");
  EXPECT_LT(measure_boundary_bend(shallow, 2).worst_angle, 20.0);
}

TEST(PatchValidity, TheConstructionAvoidsTheFoldsOfTaperedPrisms) {
  for (double taper : {0.9, 0.8, 0.7}) {
    for (const auto& f : check_patch_validity(parse_ipatch(hexagonal_prism(taper), "t.ipatch")))
      ADD_FAILURE() << "taper " << taper << ": " << f.message;
  }
}

TEST(PatchValidity, ASetbackTooShortForTheRadiiIsRefused) {
  // The steep pyramid's slanted faces have 55 degree corners and its base edges are sharp, so with
  // setback 0.45 the trimline on a slanted face runs beyond the setback plane of the slanted edge: the
  // vertex blend's region does not hold its own boundary (it used to fold there and be fanned).
  try {
    parse_ipatch(kSquarePyramidBlend, "pyramid.ipatch");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(
        m.find("vertex 1: the setback 0.450000 is too short for the blend radii there: the trimline on face"),
        std::string::npos)
        << m;
    EXPECT_NE(m.find("beyond the setback plane of edge 1-5"), std::string::npos) << m;
  }
  // A longer setback is accepted and its region holds every boundary curve.
  std::string longer = kSquarePyramidBlend;
  longer.replace(longer.find("setback 0.45"), 12, "setback 0.65");
  const Composite c = parse_ipatch(longer, "pyramid.ipatch");
  for (const CompositePatch& p : c.patches) EXPECT_LE(measure_boundary_exit(c, p).distance, 1e-12) << p.name;
}

TEST(PatchValidity, FindsNothingOnCleanPatches) {
  for (const std::string& text : {hexagonal_prism(1.0), std::string(kOctahedronBlend)}) {
    for (const auto& f : check_patch_validity(parse_ipatch(text, "clean.ipatch"))) ADD_FAILURE() << f.message;
  }
}

TEST(PatchValidity, TheSpherePatchesMeetTheirRibbonsSmoothly) {
  const Composite c = parse_ipatch(
      "ipatch-model 1\nv 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\nf 1 3 5\nf 3 2 5\nf 2 4 5\n"
      "f 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n",
      "octahedron.ipatch");
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const BoundaryBend b = measure_boundary_bend(c, p);
    EXPECT_EQ(b.missing, 0);
    EXPECT_LT(b.worst_angle, 5.0);  // the ribbons are Liming quadrics that curve as the sphere does
  }
}

}  // namespace
}  // namespace isopatch
