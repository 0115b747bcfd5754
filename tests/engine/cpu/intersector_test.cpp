#include "engine/cpu/intersector.h"
#include "tests/support/cpu_intersect.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace facet::cpu {
namespace {

using testing::aimRays;
using testing::Geometry;

// Rays of every kind the renderer casts: camera rays aimed at the surface,
// the same turned away from it, and rays leaving the surface over a finite
// segment, as shadow rays do.
std::vector<Ray> probeRays(const Geometry& geometry) {
  std::mt19937 random(7);
  std::vector<Ray> rays;
  for (const testing::AimedRay& aimed : aimRays(geometry, 48, 5)) {
    rays.push_back(aimed.ray);
    Ray away = aimed.ray;
    away.direction = -away.direction;
    rays.push_back(away);
    Ray leaving;
    leaving.origin = geometry.surface.evaluatePatch(aimed.patch, aimed.u, aimed.v).position;
    leaving.direction = testing::randomDirection(random);
    leaving.tMin = 1e-6 * geometry.diagonal;
    leaving.tMax = 0.5 * geometry.diagonal;
    rays.push_back(leaving);
  }
  return rays;
}

// closestHit is the free function's hit, bit for bit, and anyHit says
// whether there is one.
template <typename FreeFunction>
void expectSameAsFreeFunction(const Intersector& intersector, const Geometry& geometry, FreeFunction&& freeFunction) {
  int hits = 0;
  for (const Ray& ray : probeRays(geometry)) {
    const std::optional<SurfaceHit> expected = freeFunction(ray);
    const std::optional<SurfaceHit> hit = intersector.closestHit(ray);
    EXPECT_EQ(intersector.anyHit(ray), expected.has_value());
    ASSERT_EQ(hit.has_value(), expected.has_value());
    if (!hit) continue;
    ++hits;
    EXPECT_EQ(hit->t, expected->t);
    EXPECT_EQ(hit->position, expected->position);
    EXPECT_EQ(hit->geometricNormal, expected->geometricNormal);
    EXPECT_EQ(hit->shadingNormal, expected->shadingNormal);
    EXPECT_EQ(hit->patch, expected->patch);
    EXPECT_EQ(hit->ptexFace, expected->ptexFace);
    EXPECT_EQ(hit->coarseFace, expected->coarseFace);
    EXPECT_EQ(hit->u, expected->u);
    EXPECT_EQ(hit->v, expected->v);
  }
  // More hits than aimed rays: some rays that leave the surface hit it too.
  EXPECT_GT(hits, 48);
}

TEST(Intersector, ExactIsIntersectExact) {
  const Geometry geometry("creased_box");
  ExactSettings settings;
  settings.tolerance = 1e-7 * geometry.diagonal;
  const ExactIntersector intersector(geometry.surface, geometry.bvh, settings);
  expectSameAsFreeFunction(intersector, geometry, [&](const Ray& ray) {
    return intersectExact(geometry.surface, geometry.bvh, ray, settings);
  });
}

TEST(Intersector, TessellatedIsIntersectTessellated) {
  const Geometry geometry("creased_box");
  const TessellatedIntersector intersector(geometry.surface, geometry.bvh, 4);
  const TessellatedSurface tessellation = TessellatedSurface::dice(geometry.surface, 4);
  expectSameAsFreeFunction(intersector, geometry, [&](const Ray& ray) {
    return intersectTessellated(geometry.surface, geometry.bvh, tessellation, ray);
  });
}

// anyHit sees the closest hit only while it lies within the ray's segment.
TEST(Intersector, AnyHitStopsAtTMax) {
  const Geometry geometry("cube");
  const ExactIntersector exact(geometry.surface, geometry.bvh);
  const TessellatedIntersector tessellated(geometry.surface, geometry.bvh, 4);
  const Intersector* intersectors[] = {&exact, &tessellated};
  for (const Intersector* intersector : intersectors) {
    // Well inside the silhouette of the cube's z = -1 face, seen head-on.
    for (double x : {-0.3, 0.0, 0.2})
      for (double y : {-0.25, 0.1, 0.3}) {
        Ray ray;
        ray.origin = {x, y, -5.0};
        ray.direction = {0.1 * x, -0.1 * y, 1.0};
        const std::optional<SurfaceHit> hit = intersector->closestHit(ray);
        ASSERT_TRUE(hit);
        EXPECT_TRUE(intersector->anyHit(ray));
        ray.tMax = 1.001 * hit->t;
        EXPECT_TRUE(intersector->anyHit(ray));
        ray.tMax = 0.999 * hit->t;
        EXPECT_FALSE(intersector->anyHit(ray));
      }
  }
}

}  // namespace
}  // namespace facet::cpu
