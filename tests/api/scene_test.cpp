// A Scene is made by loadScene or buildScene; one made from no data is
// refused at once, not a crash at its first use.
#include <gtest/gtest.h>

#include <facet/facet.h>

namespace {

TEST(ApiScene, ASceneOfNoDataIsABadInput) {
  try {
    facet::Scene scene(nullptr);
    FAIL() << "a Scene of no data was made";
  } catch (const facet::Error& e) {
    EXPECT_EQ(e.kind(), facet::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("loadScene or buildScene"), std::string::npos);
  }
}

}  // namespace
