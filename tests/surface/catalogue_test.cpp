#include <isopatch/catalogue.hpp>

#include <gtest/gtest.h>

#include <set>

namespace isopatch {
namespace {

TEST(Catalogue, HasEveryBenchmarkSurfaceOnceWithValidBox) {
  std::set<std::string> names;
  for (const CatalogueEntry& e : catalogue()) {
    EXPECT_TRUE(names.insert(std::string(e.name)).second) << e.name;
    EXPECT_TRUE(e.box.valid()) << e.name;
    EXPECT_FALSE(e.formula.empty());
    EXPECT_EQ(e.closed, e.genus >= 0) << e.name;
  }
  for (const char* n : {"sphere", "ellipsoid", "torus", "tanglecube", "genus2", "double_torus", "chmutov6",
                        "gyroid", "blobby", "cassini", "heart"})
    EXPECT_NE(find_in_catalogue(n), nullptr) << n;
  EXPECT_EQ(find_in_catalogue("tours"), nullptr);
}

TEST(Catalogue, SuggestsClosestName) {
  EXPECT_EQ(closest_catalogue_names("tours").front(), "torus");
  EXPECT_EQ(closest_catalogue_names("sphear").front(), "sphere");
  EXPECT_EQ(closest_catalogue_names("genus_2").front(), "genus2");
}

}  // namespace
}  // namespace isopatch
