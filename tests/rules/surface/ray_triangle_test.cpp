// The ray against a triangle (rules/surface/ray_triangle.h): watertight in
// float along the edges triangles share, and where it hits, the point the
// ray meets.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <random>

#include "rules/rules.h"

namespace facet {
namespace {

namespace f32 = rules::f32;
namespace f64 = rules::f64;

// A fan of triangles around a centre, far from the origin and small, every
// two neighbours sharing an edge: the corners a float ray caster meets in a
// finely diced patch 100 units from the eye.
struct Fan {
  f32::vec3 centre{100.3f, -57.1f, 80.7f};
  std::array<f32::vec3, 7> rim;
  Fan() {
    const f32::vec3 u = glm::normalize(f32::vec3(0.3f, 0.9f, -0.2f)),
                    v = glm::normalize(glm::cross(u, f32::vec3(0.2f, 0.1f, 1.0f)));
    for (int k = 0; k < 7; ++k) {
      const float angle = 6.2831853f * float(k) / 7.0f;
      const float radius = 0.01f * (1.0f + 0.3f * float(k % 3));
      rim[k] = centre + radius * (std::cos(angle) * u + std::sin(angle) * v) + 0.002f * float(k % 2) * glm::cross(u, v);
    }
  }
  bool hit(const f32::vec3& origin, const f32::vec3& direction) const {
    for (int k = 0; k < 7; ++k) {
      f32::TriangleHit h;
      if (f32::ray_hits_triangle(f32::ray_shear(direction), origin, centre, rim[k], rim[(k + 1) % 7], h)) return true;
    }
    return false;
  }
};

TEST(RayTriangle, NoFloatRayAimedAtAnEdgeTwoTrianglesSharePassesBetweenThem) {
  const Fan fan;
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int missed = 0, rays = 0;
  for (int i = 0; i < 20000; ++i) {
    const int k = i % 7;
    // A point on a shared edge: the spoke from the centre to rim[k].
    const f32::vec3 target = glm::mix(fan.centre, fan.rim[k], 0.05f + 0.9f * unit(random));
    const f32::vec3 origin(unit(random) * 4.0f - 2.0f, unit(random) * 4.0f - 2.0f, unit(random) * 4.0f - 2.0f);
    ++rays;
    if (!fan.hit(origin, target - origin)) ++missed;
  }
  EXPECT_EQ(missed, 0) << "of " << rays << " rays aimed at shared edges";
}

TEST(RayTriangle, AHitIsThePointTheRayMeetsWithItsBarycentricWeights) {
  const f64::vec3 a(1, 0, 0), b(0, 2, 0), c(0, 0, 3), origin(2, 3, 4);
  for (const f64::vec3 weights : {f64::vec3(0.2, 0.3, 0.5), f64::vec3(0.6, 0.1, 0.3), f64::vec3(1.0 / 3.0)}) {
    const f64::vec3 target = weights.x * a + weights.y * b + weights.z * c;
    f64::TriangleHit hit;
    ASSERT_TRUE(f64::ray_hits_triangle(f64::ray_shear(0.5 * (target - origin)), origin, a, b, c, hit));
    EXPECT_NEAR(hit.t, 2.0, 1e-12);
    EXPECT_NEAR(hit.wb, weights.y, 1e-12);
    EXPECT_NEAR(hit.wc, weights.z, 1e-12);
    // From the other side, and with the direction's sign flipped: t < 0.
    ASSERT_TRUE(f64::ray_hits_triangle(f64::ray_shear(target + origin), -origin, a, b, c, hit));
    EXPECT_NEAR(hit.t, 1.0, 1e-12);
    ASSERT_TRUE(f64::ray_hits_triangle(f64::ray_shear(origin - target), origin, a, b, c, hit));
    EXPECT_NEAR(hit.t, -1.0, 1e-12);
    EXPECT_NEAR(hit.wb, weights.y, 1e-12);
  }
}

TEST(RayTriangle, ARayBesideParallelToOrThroughNoAreaMisses) {
  const f64::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  f64::TriangleHit hit;
  EXPECT_FALSE(f64::ray_hits_triangle(f64::ray_shear(f64::vec3(0, 0, -1)), f64::vec3(0.6, 0.6, 1), a, b, c, hit));
  EXPECT_FALSE(f64::ray_hits_triangle(f64::ray_shear(f64::vec3(0, 0, -1)), f64::vec3(-0.1, 0.5, 1), a, b, c, hit));
  EXPECT_FALSE(f64::ray_hits_triangle(f64::ray_shear(f64::vec3(1, 0, 0)), f64::vec3(0.2, 0.2, 0), a, b, c, hit));
  EXPECT_FALSE(f64::ray_hits_triangle(f64::ray_shear(f64::vec3(0, 0, -1)), f64::vec3(0.2, 0.0, 1), a, b, 2.0 * b, hit));
  // On an edge and on a corner: a hit.
  EXPECT_TRUE(f64::ray_hits_triangle(f64::ray_shear(f64::vec3(0, 0, -1)), f64::vec3(0.5, 0.5, 1), a, b, c, hit));
  EXPECT_TRUE(f64::ray_hits_triangle(f64::ray_shear(f64::vec3(0, 0, -1)), f64::vec3(1, 0, 1), a, b, c, hit));
  EXPECT_NEAR(hit.wb, 1.0, 1e-15);
}

}  // namespace
}  // namespace facet
