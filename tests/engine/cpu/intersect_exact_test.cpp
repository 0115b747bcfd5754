#include "tests/support/cpu_intersect.h"

#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <numbers>

namespace facet::cpu {
namespace {

using testing::aimRays;
using testing::angleBetween;
using testing::finiteDifferenceNormal;
using testing::Geometry;
using testing::randomDirection;

const std::vector<std::string> kAllCages = {"cube",          "valence_3_to_10", "pole24",
                                            "boundary_hole", "creased_box",     "ngon_prism",
                                            "thin_slab",     "nearly_flat",     "suzanne"};
// Closed and convex: rays from outside that miss a tangent plane miss all.
const std::vector<std::string> kConvexCages = {"cube", "pole24", "ngon_prism", "creased_box", "thin_slab"};

// Where dP/du x dP/dv degenerates (documented in limit_normal.h) the
// finite-difference reference degenerates with it; such points are not
// held to the normal tolerance.
bool nearDegeneratePoint(const scene::SubdivisionSurface& surface, int patch, double u, double v) {
  scene::LimitPoint point = surface.evaluatePatch(patch, u, v);
  return glm::length(glm::cross(point.du, point.dv)) < 1e-3 * glm::length(point.du) * glm::length(point.dv);
}

// OpenSubdiv's catmark_inf_crease0: a ray meets one patch twice, at t 4.297
// and 4.462, over a piece flat by the bilinear measure but twisted. Newton
// from the piece's centre finds the farther crossing; a root settles the
// piece only where the ray crosses it once, so the nearer one is found.
TEST(ExactIntersection, ARayThatCrossesATwistedPieceTwiceHitsTheNearerCrossing) {
  const scene::Scene scene =
      scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "opensubdiv" / "catmark_inf_crease0.obj");
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const scene::ObjectGeometry& object = geometry.objects[0];
  Ray ray;
  ray.origin = glm::dvec3(3.4088340345822057, 1.4966255259366541, 4.6132510518733083);
  ray.direction = glm::normalize(glm::dvec3(0.2648557, -0.08511161, 1.870423) - ray.origin);
  const std::optional<SurfaceHit> hit = intersectExact(object.surface, object.bvh, ray);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 4.2971, 1e-3);
  const scene::LimitPoint point = object.surface.evaluatePatch(hit->patch, hit->u, hit->v);
  EXPECT_LT(glm::length(point.position - ray.at(hit->t)), 1e-9 * object.surface.bounds().diagonal());
}

class ExactOnEachCage : public ::testing::TestWithParam<std::string> {};

TEST_P(ExactOnEachCage, HitsLieOnTheLimitSurfaceWithItsNormal) {
  Geometry geometry(GetParam());
  const double diagonal = geometry.diagonal;
  const std::vector<testing::AimedRay> rays = aimRays(geometry, 300, 1);
  double worstPosition = 0.0, worstRayDistance = 0.0, worstNormal = 0.0;
  int degenerate = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const testing::AimedRay& aimed : rays) {
    std::optional<SurfaceHit> hit = intersectExact(geometry.surface, geometry.bvh, aimed.ray);
    ASSERT_TRUE(hit) << "missed a ray through a surface point of patch " << aimed.patch;
    // Nothing hides the target, or something in front of it was hit.
    EXPECT_LE(hit->t, aimed.targetT + 1e-6 * diagonal);

    std::optional<scene::LimitPoint> osd = geometry.surface.evaluateFace(hit->ptexFace, hit->u, hit->v);
    ASSERT_TRUE(osd);
    worstPosition = std::max(worstPosition, glm::length(osd->position - hit->position) / diagonal);
    worstRayDistance = std::max(worstRayDistance, glm::length(aimed.ray.at(hit->t) - hit->position) / diagonal);

    const scene::PatchInfo& info = geometry.surface.patch(hit->patch);
    EXPECT_EQ(hit->ptexFace, info.ptexFace);
    EXPECT_EQ(hit->coarseFace, info.coarseFace);
    EXPECT_TRUE(hit->u >= info.domain.u0 && hit->u <= info.domain.u0 + info.domain.size);
    EXPECT_TRUE(hit->v >= info.domain.v0 && hit->v <= info.domain.v0 + info.domain.size);
    EXPECT_NEAR(glm::length(hit->shadingNormal), 1.0, 1e-12);
    if (nearDegeneratePoint(geometry.surface, hit->patch, hit->u, hit->v)) {
      ++degenerate;
      continue;
    }
    glm::dvec3 reference = finiteDifferenceNormal(geometry.surface, hit->patch, hit->u, hit->v);
    worstNormal = std::max(worstNormal, angleBetween(reference, hit->shadingNormal));
  }
  const double msPerRay =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / rays.size();
  EXPECT_LE(worstPosition, 1e-6);
  EXPECT_LE(worstRayDistance, 1e-6);
  EXPECT_LE(worstNormal, 1e-4);
  EXPECT_LE(degenerate, 3);
  RecordProperty("max_position_error_over_diagonal", std::to_string(worstPosition));
  RecordProperty("max_ray_distance_over_diagonal", std::to_string(worstRayDistance));
  RecordProperty("max_normal_error_rad", std::to_string(worstNormal));
  std::cout << GetParam() << ": " << geometry.surface.patchCount() << " patches, |P_hit-P_osd|/diag " << worstPosition
            << ", ray distance/diag " << worstRayDistance << ", normal " << worstNormal << " rad, " << msPerRay
            << " ms/ray\n";
}

INSTANTIATE_TEST_SUITE_P(TortureCages, ExactOnEachCage, ::testing::ValuesIn(kAllCages));

TEST(ExactIntersection, NoCracksInsideSilhouettes) {
  for (const std::string& name : kConvexCages) {
    Geometry geometry(name);
    testing::expectNoCracks(
        geometry, name, [&geometry](const Ray& ray) { return intersectExact(geometry.surface, geometry.bvh, ray); });
  }
}

// Rays along a tangent plane of a closed cage, passing a hair (1e-7 of the
// diagonal) inside the surface, exactly through the tangent point, or a hair
// outside. The inside ones pass through an interior point, so they must hit
// before it; every hit of any of them must be a true one. (Catmull-Clark
// does not preserve convexity, so outside rays may legitimately hit.)
TEST(ExactIntersection, GrazingAndTangentRays) {
  for (const std::string& name : {std::string("cube"), std::string("pole24"), std::string("thin_slab")}) {
    Geometry geometry(name);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    std::uniform_int_distribution<int> anyPatch(0, geometry.surface.patchCount() - 1);
    int tested = 0;
    while (tested < 30) {
      const int patch = anyPatch(random);
      const scene::PatchDomain& domain = geometry.surface.patch(patch).domain;
      const double u = domain.u0 + unit(random) * domain.size, v = domain.v0 + unit(random) * domain.size;
      if (nearDegeneratePoint(geometry.surface, patch, u, v)) continue;
      ++tested;
      const scene::LimitPoint point = geometry.surface.evaluatePatch(patch, u, v);
      glm::dvec3 normal = glm::normalize(glm::cross(point.du, point.dv));
      if (glm::dot(normal, point.position - geometry.centre) < 0.0) normal = -normal;  // outwards
      const glm::dvec3 tangent = glm::normalize(glm::cross(normal, randomDirection(random)));
      for (double offset : {1e-7, 0.0, -1e-7}) {
        Ray ray;
        ray.origin = point.position + offset * geometry.diagonal * normal - geometry.diagonal * tangent;
        ray.direction = tangent;
        std::optional<SurfaceHit> hit = intersectExact(geometry.surface, geometry.bvh, ray);
        if (offset < 0.0) {
          ASSERT_TRUE(hit) << name << ": a ray through an interior point missed";
          EXPECT_LE(hit->t, geometry.diagonal * (1.0 + 1e-9)) << name;
        }
        if (!hit) continue;
        EXPECT_LE(glm::length(ray.at(hit->t) - hit->position), 1e-6 * geometry.diagonal);
        std::optional<scene::LimitPoint> osd = geometry.surface.evaluateFace(hit->ptexFace, hit->u, hit->v);
        ASSERT_TRUE(osd);
        EXPECT_LE(glm::length(osd->position - hit->position), 1e-6 * geometry.diagonal);
      }
    }
  }
}

// Secondary rays start on the surface with a small tMin: leaving a convex
// cage they must miss it, entering it they must reach the far side.
TEST(ExactIntersection, RaysLeavingTheSurfaceDoNotHitThemselves) {
  for (const std::string& name : {std::string("cube"), std::string("pole24"), std::string("ngon_prism")}) {
    Geometry geometry(name);
    std::mt19937 random(23);
    int leaving = 0, entering = 0;
    for (const testing::AimedRay& aimed : aimRays(geometry, 60, 5)) {
      std::optional<SurfaceHit> first = intersectExact(geometry.surface, geometry.bvh, aimed.ray);
      ASSERT_TRUE(first);
      // These cages wind their faces counter-clockwise from outside.
      const glm::dvec3 outwards = first->shadingNormal;
      EXPECT_GT(glm::dot(outwards, first->position - geometry.centre), 0.0) << name;
      for (int k = 0; k < 4; ++k) {
        Ray ray;
        ray.origin = first->position;
        ray.direction = randomDirection(random);
        ray.tMin = 1e-6 * geometry.diagonal;
        const double cosine = glm::dot(ray.direction, outwards);
        if (std::abs(cosine) < 0.05) continue;
        std::optional<SurfaceHit> second = intersectExact(geometry.surface, geometry.bvh, ray);
        if (cosine > 0.0) {
          EXPECT_FALSE(second) << name << ": self-hit at t " << second->t;
          ++leaving;
        } else {
          ASSERT_TRUE(second) << name << ": ray into a closed cage escaped";
          EXPECT_GT(second->t, 1e-3 * geometry.diagonal) << name << ": self-hit";
          ++entering;
        }
      }
    }
    EXPECT_GT(leaving, 50);
    EXPECT_GT(entering, 50);
  }
}

// Nearly flat patches seen at a glancing angle: the rays still find the
// point they were aimed at.
TEST(ExactIntersection, GlancingRaysOnNearlyFlatPatches) {
  Geometry geometry("nearly_flat");
  std::mt19937 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double elevation : {0.3, 1e-2, 1e-3}) {
    for (const testing::AimedRay& aimed : aimRays(geometry, 40, 31)) {
      const scene::LimitPoint target = geometry.surface.evaluatePatch(aimed.patch, aimed.u, aimed.v);
      const double azimuth = 2.0 * std::numbers::pi * unit(random);
      const glm::dvec3 towards(std::cos(azimuth) * std::cos(elevation), std::sin(azimuth) * std::cos(elevation),
                               -std::sin(elevation));
      Ray ray;
      ray.origin = target.position - geometry.diagonal * towards;
      ray.direction = towards;
      std::optional<SurfaceHit> hit = intersectExact(geometry.surface, geometry.bvh, ray);
      ASSERT_TRUE(hit) << "elevation " << elevation;
      EXPECT_LE(hit->t, geometry.diagonal * (1.0 + 1e-6));
      EXPECT_LE(glm::length(ray.at(hit->t) - hit->position), 1e-6 * geometry.diagonal);
    }
  }
}

TEST(ExactIntersection, RespectsTheRaySegment) {
  Geometry geometry("cube");
  Ray ray;
  ray.origin = {0.1, 0.2, -5.0};
  ray.direction = {0.0, 0.0, 1.0};
  std::optional<SurfaceHit> hit = intersectExact(geometry.surface, geometry.bvh, ray);
  ASSERT_TRUE(hit);
  ray.tMax = hit->t * 0.999;
  EXPECT_FALSE(intersectExact(geometry.surface, geometry.bvh, ray));
  ray.tMax = std::numeric_limits<double>::infinity();
  ray.tMin = hit->t * 1.001;
  std::optional<SurfaceHit> far = intersectExact(geometry.surface, geometry.bvh, ray);
  ASSERT_TRUE(far);
  EXPECT_GT(far->position.z, 0.0);
  ray.direction = {0.0, 1.0, 0.0};
  EXPECT_FALSE(intersectExact(geometry.surface, geometry.bvh, ray));
  ray.tMin = 0.0;
  ray.direction = {0.0, 0.0, 0.0};
  EXPECT_FALSE(intersectExact(geometry.surface, geometry.bvh, ray));
  ray.direction = {0.0, std::nan(""), 1.0};
  EXPECT_FALSE(intersectExact(geometry.surface, geometry.bvh, ray));
  EXPECT_FALSE(
      intersectTessellated(geometry.surface, geometry.bvh, TessellatedSurface::dice(geometry.surface, 2), ray));
}

}  // namespace
}  // namespace facet::cpu
