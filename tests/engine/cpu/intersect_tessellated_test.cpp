#include "tests/support/cpu_intersect.h"

#include <gtest/gtest.h>

#include <iostream>

namespace facet::cpu {
namespace {

using testing::aimRays;
using testing::Geometry;

TEST(TessellatedIntersection, GridPointsAreLimitPoints) {
  Geometry geometry("ngon_prism");
  TessellatedSurface tessellation = TessellatedSurface::dice(geometry.surface, 4);
  for (int patch = 0; patch < geometry.surface.patchCount(); patch += 7) {
    const scene::PatchDomain& domain = geometry.surface.patch(patch).domain;
    const glm::dvec3 expected =
        geometry.surface.evaluatePatch(patch, domain.u0 + 0.75 * domain.size, domain.v0 + 0.25 * domain.size).position;
    EXPECT_EQ(tessellation.vertex(patch, 3, 1), expected);
  }
}

// Depth error against the exact limit surface shrinks ~4x per doubling of
// the dicing rate (second-order chord error).
TEST(TessellatedIntersection, DepthConvergesToExactAtSecondOrder) {
  Geometry geometry("pole24");
  const double diagonal = geometry.diagonal;
  std::vector<testing::AimedRay> rays;
  std::vector<double> exactT;
  for (const testing::AimedRay& aimed : aimRays(geometry, 400, 41)) {
    std::optional<SurfaceHit> hit = intersectExact(geometry.surface, geometry.bvh, aimed.ray);
    // Glancing rays measure the silhouette, not the depth: keep steep ones.
    if (!hit || std::abs(glm::dot(hit->shadingNormal, aimed.ray.direction)) < 0.3) continue;
    rays.push_back(aimed);
    exactT.push_back(hit->t);
  }
  ASSERT_GT(rays.size(), 150u);

  std::vector<double> meanError;
  for (int rate : {2, 4, 8, 16, 32}) {
    TessellatedSurface tessellation = TessellatedSurface::dice(geometry.surface, rate);
    double sum = 0.0;
    int count = 0;
    for (size_t r = 0; r < rays.size(); ++r) {
      std::optional<SurfaceHit> hit = intersectTessellated(geometry.surface, geometry.bvh, tessellation, rays[r].ray);
      ASSERT_TRUE(hit) << "rate " << rate;
      EXPECT_NEAR(glm::length(hit->geometricNormal), 1.0, 1e-12);
      EXPECT_LE(glm::length(rays[r].ray.at(hit->t) - hit->position), 1e-12 * diagonal);
      sum += std::abs(hit->t - exactT[r]) / diagonal;
      ++count;
    }
    meanError.push_back(sum / count);
  }
  std::cout << "mean |t_tess - t_exact| / diag for k = 2..32:";
  for (double e : meanError) std::cout << " " << e;
  std::cout << "\nreduction per doubling of k:";
  for (size_t i = 1; i < meanError.size(); ++i) {
    const double ratio = meanError[i - 1] / meanError[i];
    std::cout << " " << ratio;
    RecordProperty("ratio_k" + std::to_string(1 << i) + "_to_k" + std::to_string(2 << i), std::to_string(ratio));
    if (i >= 2) {
      EXPECT_GT(ratio, 3.0);
      EXPECT_LT(ratio, 5.5);
    }
  }
  std::cout << "\n";
  EXPECT_LT(meanError.back(), 1e-4);
}

// Rays aimed at limit points (a quarter of them on patch boundaries, where
// neighbours of different depth meet): steep ones must all hit the
// tessellation; near a silhouette (or a sharp crease) the chords of a convex
// surface lie inside it, so a ray glancing off the limit surface may pass it.
TEST(TessellatedIntersection, HitsReportPatchFaceAndParameters) {
  Geometry geometry("creased_box");
  for (int rate : {3, 8}) {
    TessellatedSurface tessellation = TessellatedSurface::dice(geometry.surface, rate);
    for (const testing::AimedRay& aimed : aimRays(geometry, 400, 43)) {
      std::optional<SurfaceHit> hit = intersectTessellated(geometry.surface, geometry.bvh, tessellation, aimed.ray);
      const scene::LimitPoint target = geometry.surface.evaluatePatch(aimed.patch, aimed.u, aimed.v);
      const bool glancing =
          std::abs(glm::dot(glm::normalize(glm::cross(target.du, target.dv)), aimed.ray.direction)) < 0.3;
      // A point on an infinitely sharp crease is an edge of the
      // surface: chords cut inside it just as at a silhouette.
      const scene::PatchInfo& aimedAt = geometry.surface.patch(aimed.patch);
      const double s = (aimed.u - aimedAt.domain.u0) / aimedAt.domain.size,
                   t = (aimed.v - aimedAt.domain.v0) / aimedAt.domain.size;
      const unsigned sharp = aimedAt.boundaryMask;
      const bool onSharpEdge = (t == 0.0 && (sharp & 1u)) || (s == 1.0 && (sharp & 2u)) || (t == 1.0 && (sharp & 4u)) ||
                               (s == 0.0 && (sharp & 8u));
      if (!hit && (glancing || onSharpEdge)) continue;
      ASSERT_TRUE(hit) << "k = " << rate << ": missed a steep ray aimed at patch " << aimed.patch;
      const scene::PatchInfo& info = geometry.surface.patch(hit->patch);
      EXPECT_EQ(hit->ptexFace, info.ptexFace);
      EXPECT_EQ(hit->coarseFace, info.coarseFace);
      EXPECT_GE(hit->u, info.domain.u0);
      EXPECT_LE(hit->u, info.domain.u0 + info.domain.size);
      EXPECT_GE(hit->v, info.domain.v0);
      EXPECT_LE(hit->v, info.domain.v0 + info.domain.size);
      // The micro-triangle point is within the dicing error of the
      // limit point at the reported (u, v).
      const glm::dvec3 limit = geometry.surface.evaluatePatch(hit->patch, hit->u, hit->v).position;
      EXPECT_LE(glm::length(limit - hit->position), 0.05 * geometry.diagonal / (rate * rate));
      EXPECT_GT(glm::dot(hit->geometricNormal, hit->shadingNormal), 0.5);
    }
  }
}

// Split transition edges make the grids of neighbours of different depth
// meet vertex to vertex: no slits, at any rate.
TEST(TessellatedIntersection, NoCracksInsideSilhouettes) {
  for (const std::string& name :
       {std::string("cube"), std::string("pole24"), std::string("creased_box"), std::string("ngon_prism")}) {
    Geometry geometry(name);
    for (int rate : {1, 2, 5}) {
      TessellatedSurface tessellation = TessellatedSurface::dice(geometry.surface, rate);
      testing::expectNoCracks(geometry, name + " k=" + std::to_string(rate), [&](const Ray& ray) {
        return intersectTessellated(geometry.surface, geometry.bvh, tessellation, ray);
      });
    }
  }
}

// Random rays through the bounds of every cage: the two families see the
// same surface (a dense tessellation is a second opinion on missed roots).
// Hit or miss may differ only within the dicing error of a silhouette, and
// the exact hit is never behind the tessellated one by more than that.
TEST(TessellatedIntersection, AgreesWithExactOnRandomRays) {
  for (const std::string& name : {std::string("cube"), std::string("valence_3_to_10"), std::string("pole24"),
                                  std::string("boundary_hole"), std::string("creased_box"), std::string("ngon_prism"),
                                  std::string("thin_slab"), std::string("nearly_flat"), std::string("suzanne")}) {
    Geometry geometry(name);
    TessellatedSurface tessellation = TessellatedSurface::dice(geometry.surface, 16);
    const glm::dvec3 centre = geometry.centre;
    std::mt19937 random(99);
    std::uniform_real_distribution<double> offset(-0.4, 0.4);
    int disagreements = 0, hits = 0;
    constexpr int kRays = 500;
    for (int i = 0; i < kRays; ++i) {
      Ray ray;
      ray.origin = centre + 1.5 * geometry.diagonal * testing::randomDirection(random);
      // Drawn z first, in sequence (see randomDirection).
      const double z = offset(random), y = offset(random), x = offset(random);
      ray.direction = glm::normalize(centre + geometry.diagonal * glm::dvec3(x, y, z) - ray.origin);
      std::optional<SurfaceHit> exact = intersectExact(geometry.surface, geometry.bvh, ray);
      std::optional<SurfaceHit> diced = intersectTessellated(geometry.surface, geometry.bvh, tessellation, ray);
      hits += exact.has_value();
      if (exact.has_value() != diced.has_value()) {
        ++disagreements;
        continue;
      }
      if (exact) {
        EXPECT_LE(exact->t, diced->t + 1e-3 * geometry.diagonal) << name;
      }
    }
    EXPECT_LE(disagreements, kRays / 200) << name;
    EXPECT_GT(hits, kRays / 20) << name;
  }
}

}  // namespace
}  // namespace facet::cpu
