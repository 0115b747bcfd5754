// When one root settles a piece of a patch (rules/surface/piece_slope.h).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

#include "rules/rules.h"

namespace facet {
namespace {

namespace m = rules::f64;

TEST(PieceSlope, TheBoundIsMarkovsNineTimesTheThicknessOverTheWidth) {
  EXPECT_DOUBLE_EQ(m::piece_slope_bound(0.01, 0.5), 9 * 0.02);
  EXPECT_DOUBLE_EQ(m::piece_slope_bound(0.0, 0.5), 0.0);
  // A piece with no width across bounds nothing.
  EXPECT_TRUE(std::isinf(m::piece_slope_bound(0.01, 0.0)));
}

TEST(PieceSlope, ARayIsSteepWhereItRisesFasterThanTheBoundAcrossThePlane) {
  const m::vec3 up(0, 0, 1);
  // 45 degrees to the plane: slope 1.
  const m::vec3 diagonal = glm::normalize(m::vec3(1, 0, -1));
  EXPECT_TRUE(m::steeper_than(diagonal, up, 0.99));
  EXPECT_FALSE(m::steeper_than(diagonal, up, 1.01));
  // Along the normal every slope is exceeded but an infinite one; in the
  // plane none is, not even a flat piece's.
  EXPECT_TRUE(m::steeper_than(-up, up, 1e12));
  EXPECT_FALSE(m::steeper_than(-up, up, m::INFINITE_DISTANCE));
  EXPECT_FALSE(m::steeper_than(m::vec3(1, 0, 0), up, 0.0));
  // The direction's length does not matter.
  EXPECT_EQ(m::steeper_than(3.0 * diagonal, up, 0.99), m::steeper_than(diagonal, up, 0.99));
}

}  // namespace
}  // namespace facet
