// Paths on the CPU reference (engine/cpu/path_tracer.h) against what is known
// exactly: the interreflection inside a closed diffuse sphere lit from its
// centre, Russian roulette's mean, a convex object that no continuation finds,
// and bounces = 0 as the renderer without paths, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/cpu/reference_renderer.h"
#include "scenes/scene_geometry.h"
#include "tests/support/blob_scene.h"
#include "tests/support/inside_sphere.h"

namespace facet {
namespace {

using testing::geometricSum;
using testing::meanRadiance;
using testing::PixelMean;

scene::Scene insideSphere(double albedo, int bounces) { return testing::insideDiffuseSphere(albedo, bounces, 48, 16); }

struct PathRender {
  Image image;
  cpu::ReferenceStatistics statistics;
};

PathRender renderOnCpu(const scene::Scene& scene) {
  PathRender r;
  r.image = cpu::renderReference(scene, scene::buildGeometry(scene), &r.statistics);
  return r;
}

TEST(PathTracer, InsideADiffuseSphereEachBounceAddsTheAlbedoTimesTheLast) {
  const double albedo = 0.5;
  const double direct = meanRadiance(renderOnCpu(insideSphere(albedo, 0)).image).mean;
  std::printf("bounces  0: mean %.5f, L0 = rho %.5f\n", direct, albedo);
  EXPECT_NEAR(direct, albedo, 0.01 * albedo);  // L0 = rho, to the polygon sphere's flatness
  double previous = direct, previousContribution = direct;
  for (int bounces : {1, 2, 24}) {
    const double mean = meanRadiance(renderOnCpu(insideSphere(albedo, bounces)).image).mean;
    const double expected = direct * geometricSum(albedo, bounces + 1);
    std::printf("bounces %2d: mean %.5f, L0 sum %.5f, relative error %.2e\n", bounces, mean, expected,
                mean / expected - 1);
    EXPECT_NEAR(mean, expected, 0.015 * expected) << bounces << " bounces";
    if (bounces <= 2) {  // before roulette, each bounce adds rho times the one before
      const double contribution = mean - previous;
      EXPECT_NEAR(contribution / previousContribution, albedo, 0.01) << bounces << " bounces";
      previousContribution = contribution;
    }
    previous = mean;
  }
}

TEST(PathTracer, RussianRouletteKeepsTheMean) {
  const double albedo = 0.8;
  const int bounces = 12;
  const PathRender r = renderOnCpu(insideSphere(albedo, bounces));
  const std::vector<cpu::BounceRays>& rays = r.statistics.raysPerBounce;
  ASSERT_EQ(rays.size(), std::size_t(bounces) + 1);
  // Up to bounce 2 every path continues (the sphere is closed); from bounce 3
  // on roulette ends some.
  EXPECT_EQ(rays[2].rays, rays[1].rays);
  EXPECT_LT(double(rays[3].rays), 0.8 * double(rays[2].rays));
  EXPECT_LT(rays[bounces].rays, rays[3].rays);
  // Without roulette every throughput here is exactly rho^k (cosine
  // sampling of a Lambertian lobe), so its mean is L0 (1 + ... + rho^N):
  // roulette must land within 4 standard errors of it.
  const PixelMean mean = meanRadiance(r.image);
  const double expected = albedo * geometricSum(albedo, bounces + 1);
  std::printf("roulette: mean %.5f +- %.5f, without roulette %.5f\n", mean.mean, mean.standardError, expected);
  EXPECT_GT(mean.standardError, 0.0);
  EXPECT_NEAR(mean.mean, expected, 4 * mean.standardError + 0.005 * expected);
}

// Settings as the render left them: bounces at their default.
scene::Scene blobUnderWhite() {
  scene::Scene s = testing::blobUnder(
      testing::lambertian(0.8),
      std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0))), 16);
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->samples = 4;
  return s;
}

scene::Scene blobUnderWhite(int bounces) {
  scene::Scene s = blobUnderWhite();
  s.render.bounces = bounces;
  return s;
}

TEST(PathTracer, NoContinuationLeavingAConvexObjectFindsIt) {
  const PathRender direct = renderOnCpu(blobUnderWhite(0));
  const PathRender paths = renderOnCpu(blobUnderWhite(3));
  const cpu::BounceRays& first = paths.statistics.raysPerBounce.at(1);
  std::printf("continuations from vertex 1: %llu, of which %llu hit\n", (unsigned long long)first.rays,
              (unsigned long long)first.hits);
  EXPECT_GT(first.rays, 100u);
  EXPECT_LE(first.hits, first.rays / 1000);  // self-hits only, at the shadow offset's scale
  // Where no continuation hits, vertex 1 draws the same numbers as without paths.
  std::size_t differing = 0;
  for (std::size_t p = 0; p < direct.image.pixelCount(); ++p)
    differing += direct.image.beauty[p] != paths.image.beauty[p];
  EXPECT_LE(differing, first.hits);
}

TEST(PathTracer, ZeroBouncesIsTheRendererWithoutPathsBitForBit) {
  const scene::Scene explicitZero = blobUnderWhite(0);
  const Image a = renderOnCpu(blobUnderWhite()).image;
  const Image b = renderOnCpu(explicitZero).image;
  for (std::size_t p = 0; p < a.pixelCount(); ++p) {
    ASSERT_EQ(a.beauty[p], b.beauty[p]) << p;
    ASSERT_EQ(a.depth[p], b.depth[p]) << p;
    ASSERT_EQ(a.position[p], b.position[p]) << p;
    ASSERT_EQ(a.geometricNormal[p], b.geometricNormal[p]) << p;
    ASSERT_EQ(a.shadingNormal[p], b.shadingNormal[p]) << p;
    ASSERT_EQ(a.patchId[p], b.patchId[p]) << p;
    ASSERT_EQ(a.faceId[p], b.faceId[p]) << p;
    ASSERT_EQ(a.uv[p], b.uv[p]) << p;
    ASSERT_EQ(a.texcoord[p], b.texcoord[p]) << p;
  }
  EXPECT_TRUE(renderOnCpu(explicitZero).statistics.raysPerBounce.empty());
}

TEST(PathTracer, PathsNeedTheEnvironmentsShadowRays) {
  scene::Scene unshadowed = blobUnderWhite(1);
  unshadowed.environment->occlusion = false;
  EXPECT_THROW(renderOnCpu(unshadowed), std::invalid_argument);
  scene::Scene prefiltered = blobUnderWhite(1);
  prefiltered.environment->method = scene::IblMethod::Prefiltered;
  EXPECT_THROW(renderOnCpu(prefiltered), std::invalid_argument);
}

}  // namespace
}  // namespace facet
