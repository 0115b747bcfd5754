// The crossing of a ray that leaves a transmissive surface
// (rules/surface/crossing.h): which hits near the vertex it passes over.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "rules/rules.h"

namespace facet {
namespace {

namespace m = rules::f64;

const m::vec3 kUp(0, 0, 1);  // the outward normal of the surface left
constexpr double kOffset = 1e-3;

TEST(SurfaceCrossing, ARayIntoTheSolidStartsTheOffsetOutsideAndKeepsOnlyTheFarSideNearIt) {
  const m::vec3 down = glm::normalize(m::vec3(0.6, 0, -0.8));
  const m::SurfaceCrossing c = m::surface_crossing(down, kUp, true, kOffset);
  EXPECT_TRUE(c.inside);
  EXPECT_NEAR(c.back, kOffset / 0.8, 1e-15);
  // Back along its way, one offset above the surface's plane.
  EXPECT_NEAR(glm::dot(m::crossing_origin(c, m::vec3(0), down), kUp), kOffset, 1e-15);
  // The surface it left, met again about `back` along: passed over.
  EXPECT_TRUE(m::crossing_passes_over(c, true, c.back, down, kUp));
  // The far side of a slab 1e-9 thick, facing the ray as a surface it leaves: kept.
  EXPECT_FALSE(m::crossing_passes_over(c, true, c.back + 1e-9, down, -kUp));
  // Another object's surface touching the vertex: passed over, as the offset did.
  EXPECT_TRUE(m::crossing_passes_over(c, false, c.back + 1e-9, down, -kUp));
  EXPECT_TRUE(m::crossing_passes_over(c, false, c.back + 1e-9, down, kUp));
  // Beyond twice `back` every hit counts.
  EXPECT_FALSE(m::crossing_passes_over(c, true, 2 * c.back, down, kUp));
  EXPECT_FALSE(m::crossing_passes_over(c, false, 2 * c.back, down, kUp));
}

TEST(SurfaceCrossing, ARayIntoAirPassesOverEverythingNearTheVertex) {
  const m::vec3 up = glm::normalize(m::vec3(0, 0.6, 0.8));
  // Refracted out of a solid whose v is inside: the geometric normal faces v, -kUp.
  const m::SurfaceCrossing c = m::surface_crossing(up, -kUp, false, kOffset);
  EXPECT_FALSE(c.inside);
  EXPECT_TRUE(m::crossing_passes_over(c, true, c.back, up, kUp));
  EXPECT_TRUE(m::crossing_passes_over(c, true, c.back + 1e-9, up, -kUp));
  EXPECT_FALSE(m::crossing_passes_over(c, true, 2 * c.back, up, -kUp));
  // Reflected back inside from there: into the solid again.
  EXPECT_TRUE(m::surface_crossing(-up, -kUp, false, kOffset).inside);
}

TEST(SurfaceCrossing, AGrazingRayBacksUpNoFurtherThanTheCapAndNoneBacksUpWithout) {
  const m::vec3 grazing = glm::normalize(m::vec3(1, 0, -1e-6));
  EXPECT_NEAR(m::surface_crossing(grazing, kUp, true, kOffset).back, kOffset / m::CROSSING_MIN_COSINE, 1e-15);
  const m::SurfaceCrossing none = m::no_crossing();
  EXPECT_FALSE(m::crossing_passes_over(none, true, 0.0, grazing, kUp));
  EXPECT_EQ(m::crossing_origin(none, m::vec3(1, 2, 3), grazing), m::vec3(1, 2, 3));
}

}  // namespace
}  // namespace facet
