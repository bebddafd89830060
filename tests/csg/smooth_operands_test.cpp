// The smooth operands of a CSG formula (csg/smooth_operands.hpp) and the singular points of a shape
// searched on them (find_shape_singular_points, isopatch.hpp): a cone's apex on the shape is found, one
// cut away is not, and the creases of a capped lattice no longer send the search to its budget.
#include <gtest/gtest.h>

#include <isopatch/isopatch.hpp>
#include <isopatch/resolve_surface.hpp>
#include <isopatch/singular_points.hpp>

#include <optional>
#include <string>
#include <vector>

#include "csg/smooth_operands.hpp"
#include "part_checks.hpp"

namespace isopatch {
namespace smooth_operands_test {

TEST(SmoothOperands, EveryLeafOnceRootFirstAndNoneForASmoothFormula) {
  const Box box = test::cube_box(2.0);
  const SurfacePtr f = expression_surface("max(max(x-1,y-1),min(z-1,x*x+y*y-1))", box);
  const std::optional<std::vector<SurfacePtr>> operands = smooth_operands(*f, box, 64);
  ASSERT_TRUE(operands);
  ASSERT_EQ(operands->size(), 4u);
  const Vec3 p(0.3, -0.2, 0.7);
  std::vector<double> values;
  for (const SurfacePtr& o : *operands) values.push_back(o->value(p));
  std::sort(values.begin(), values.end());
  const std::vector<double> expected = {p.x() - 1, p.y() - 1, p.z() - 1, p.x() * p.x() + p.y() * p.y() - 1};
  std::vector<double> sorted = expected;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(values[k], sorted[k], 1e-15);
  EXPECT_FALSE(smooth_operands(*expression_surface("x*x+y*y+z*z-1", box), box, 64));
  EXPECT_FALSE(smooth_operands(*f, box, 3));  // more operands than allowed
  // abs(g) is max(g, -g): two operands, the outer steps kept.
  const std::optional<std::vector<SurfacePtr>> sheet =
      smooth_operands(*expression_surface("2*abs(x-0.5)-0.3", box), box, 64);
  ASSERT_TRUE(sheet);
  ASSERT_EQ(sheet->size(), 2u);
  EXPECT_NEAR(std::max((*sheet)[0]->value(p), (*sheet)[1]->value(p)), 2 * std::abs(p.x() - 0.5) - 0.3, 1e-15);
}

TEST(ShapeSingularPoints, AConesApexOnTheShapeIsFoundOneCutAwayIsNot) {
  const Box box = test::cube_box(2.0);
  const SingularPoints capped =
      find_shape_singular_points(*expression_surface("max(x*x+y*y-z*z,z*z-1)", box), box);
  EXPECT_EQ(capped.status, SingularSearchStatus::Complete);
  ASSERT_EQ(capped.isolated_points(), 1u);
  EXPECT_LT(capped.components.front().position.norm(), 1e-6);
  // The apex lies where 0.5 - z > 0 = the cone: f is 0.5 there, off the shape.
  const SingularPoints cut =
      find_shape_singular_points(*expression_surface("max(x*x+y*y-z*z,0.5-z)", box), box);
  EXPECT_EQ(cut.status, SingularSearchStatus::Complete);
  EXPECT_TRUE(cut.components.empty());
}

TEST(ShapeSingularPoints, ALatticeSheetInABallIsSearchedToTheEndAlongItsCreases) {
  // Searched on f itself, the boxes along the sheet's creases with the ball are never excluded: 830
  // thousand enclosures (3 s; a ball of radius 6 reaches the budget of a million); on the three operands
  // the search ends complete in under a tenth of that.
  const std::string n = "3*(cos(x)+cos(y)+cos(z))+4*cos(x)*cos(y)*cos(z)";
  const Box box = test::cube_box(3.3);
  SingularSearchSettings s;
  s.min_box_size = 0.25 * 0.1;
  const SingularPoints found =
      find_shape_singular_points(*expression_surface("max(abs(" + n + ")-0.3,x*x+y*y+z*z-9)", box), box, s);
  EXPECT_EQ(found.status, SingularSearchStatus::Complete);
  EXPECT_TRUE(found.components.empty());
  EXPECT_LT(found.boxes, 100000u);
}

}  // namespace smooth_operands_test
}  // namespace isopatch
