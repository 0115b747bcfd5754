#include <gtest/gtest.h>

#include <cmath>

#include "engine/image/color.h"

namespace facet {
namespace {

TEST(Srgb, EndpointsAreFixed) {
  EXPECT_DOUBLE_EQ(linearToSrgb(0.0), 0.0);
  EXPECT_NEAR(linearToSrgb(1.0), 1.0, 1e-15);
}

TEST(Srgb, LinearAndPowerPiecesMeetAtTheJoint) {
  const double joint = 0.0031308;
  EXPECT_NEAR(linearToSrgb(joint), 0.0404500, 1e-6);
  EXPECT_NEAR(linearToSrgb(std::nextafter(joint, 1.0)), linearToSrgb(joint), 1e-7);
}

TEST(Srgb, KnownValues) {
  EXPECT_NEAR(linearToSrgb(0.5), 0.7353569830524495, 1e-12);
  EXPECT_NEAR(linearToSrgb(0.18), 0.4613561295004416, 1e-12);  // photographic middle grey
  const glm::dvec3 encoded = linearToSrgb(glm::dvec3(0.0, 0.5, 1.0));
  EXPECT_EQ(encoded, glm::dvec3(linearToSrgb(0.0), linearToSrgb(0.5), linearToSrgb(1.0)));
}

}  // namespace
}  // namespace facet
