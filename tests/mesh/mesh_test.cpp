// The Mesh container: named attributes and structural validation.
#include <isopatch/error.hpp>
#include <isopatch/mesh.hpp>

#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace isopatch {
namespace {

TEST(Mesh, AttributesAreAddedInOrderAndReplacedByName) {
  Mesh m = test::octahedron();
  m.set_attribute("k", std::vector<float>(6, 1.0f));
  m.set_attribute("_err2", std::vector<float>(6, 2.0f));
  m.set_attribute("k", std::vector<float>(6, 3.0f));
  ASSERT_EQ(m.attributes.size(), 2u);
  EXPECT_EQ(m.attributes[0].name, "k");
  EXPECT_EQ(m.attributes[1].name, "_err2");
  ASSERT_NE(m.find_attribute("k"), nullptr);
  EXPECT_EQ((*m.find_attribute("k"))[5], 3.0f);
  EXPECT_EQ(m.find_attribute("missing"), nullptr);
  EXPECT_NO_THROW(m.validate());
}

TEST(Mesh, RejectsBadAttributeNamesAndSizes) {
  Mesh m = test::octahedron();
  for (const char* name : {"", "1k", "a-b", "a b", "k\n"})
    EXPECT_THROW(m.set_attribute(name, std::vector<float>(6)), InputError) << name;
  EXPECT_THROW(m.set_attribute("k", std::vector<float>(5)), InputError);
  EXPECT_THROW(m.set_attribute("k", std::vector<float>(7)), InputError);
  EXPECT_TRUE(m.attributes.empty());
}

TEST(Mesh, ValidateFindsEachKindOfViolation) {
  EXPECT_NO_THROW(test::octahedron().validate());
  EXPECT_NO_THROW(Mesh{}.validate());

  Mesh out_of_range = test::octahedron();
  out_of_range.triangles[3][1] = 6;
  EXPECT_THROW(out_of_range.validate(), InputError);

  Mesh repeated = test::octahedron();
  repeated.triangles[2] = {1, 4, 1};
  EXPECT_THROW(repeated.validate(), InputError);

  Mesh not_finite = test::octahedron();
  not_finite.positions[4].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(not_finite.validate(), InputError);
  not_finite.positions[4].y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(not_finite.validate(), InputError);

  Mesh short_attribute = test::octahedron();
  short_attribute.set_attribute("k", std::vector<float>(6));
  short_attribute.attributes[0].values.pop_back();
  EXPECT_THROW(short_attribute.validate(), InputError);
}

TEST(Mesh, BoundingBox) {
  EXPECT_FALSE(bounding_box(Mesh{}).valid());
  const Box b = bounding_box(test::octahedron());
  EXPECT_EQ(b.lo, Vec3::Constant(-1.0));
  EXPECT_EQ(b.hi, Vec3::Constant(1.0));
}

}  // namespace
}  // namespace isopatch
