// Paths on the CPU reference (engine/cpu/path_tracer.h) against what is known
// exactly: the interreflection inside a closed diffuse sphere lit from its
// centre, Russian roulette's mean, a convex object that no continuation finds,
// and bounces = 0 as the renderer without paths, bit for bit.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/cpu/reference_renderer.h"
#include "engine/renderer.h"
#include "scenes/scene_geometry.h"
#include "tests/support/blob_scene.h"

namespace facet {
namespace {

// A UV sphere of radius 1 about the origin, `rings` x `segments` faces
// (quads, and triangles at the poles), rendered as authored.
scene::ControlCage uvSphere(int rings, int segments) {
  scene::ControlCage cage;
  cage.source = "uv sphere";
  cage.positions.push_back({0.0, 1.0, 0.0});
  for (int ring = 1; ring < rings; ++ring) {
    const double theta = glm::pi<double>() * ring / rings;
    for (int segment = 0; segment < segments; ++segment) {
      const double phi = 2.0 * glm::pi<double>() * segment / segments;
      cage.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
    }
  }
  cage.positions.push_back({0.0, -1.0, 0.0});
  const int south = int(cage.positions.size()) - 1;
  auto at = [&](int ring, int segment) { return 1 + (ring - 1) * segments + segment % segments; };
  auto face = [&](std::vector<int> vertices) {
    cage.faceVertexCounts.push_back(int(vertices.size()));
    cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), vertices.begin(), vertices.end());
  };
  for (int s = 0; s < segments; ++s) {
    face({0, at(1, s + 1), at(1, s)});
    for (int ring = 1; ring + 1 < rings; ++ring)
      face({at(ring, s), at(ring, s + 1), at(ring + 1, s + 1), at(ring + 1, s)});
    face({south, at(rings - 1, s), at(rings - 1, s + 1)});
  }
  return cage;
}

// The camera and a point light of c_light = 1 at the centre of a closed
// Lambertian sphere of albedo rho: every point receives irradiance pi, so
// the direct radiance is L0 = rho everywhere and each bounce multiplies it
// by rho (pbrt-v4's sphere test: Kd 0.5 gives 0.5 direct, 1.0 converged).
scene::Scene insideSphere(double albedo, int bounces) {
  scene::Scene s;
  s.materials.push_back(testing::lambertian(albedo));
  scene::Object sphere;
  sphere.name = "sphere";
  sphere.cage = uvSphere(32, 64);
  sphere.subdivision = scene::Subdivision::None;
  s.objects.push_back(std::move(sphere));
  scene::Light light;
  light.type = scene::LightType::Point;
  light.position = glm::dvec3(0.0);
  s.lights.push_back(light);
  s.camera.eye = glm::dvec3(0.0);
  s.camera.target = {0.0, 0.2, -1.0};
  s.camera.verticalFovDegrees = 90;
  s.render.width = s.render.height = 48;
  s.render.samplesPerPixel = 16;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.render.bounces = bounces;
  return s;
}

struct PathRender {
  Image image;
  cpu::ReferenceStatistics statistics;
};

PathRender renderOnCpu(const scene::Scene& scene) {
  PathRender r;
  r.image = cpu::renderReference(scene, scene::buildGeometry(scene), &r.statistics);
  return r;
}

struct PixelMean {
  double mean = 0;
  double standardError = 0;  // of the mean, from the pixels' spread
};

PixelMean meanRadiance(const Image& image) {
  double sum = 0, sumSquares = 0;
  for (const glm::vec4& pixel : image.beauty) {
    const double value = (double(pixel.r) + double(pixel.g) + double(pixel.b)) / 3.0;
    sum += value;
    sumSquares += value * value;
  }
  const double n = double(image.beauty.size());
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sumSquares / n - mean * mean) / (n - 1))};
}

double geometricSum(double ratio, int terms) {
  double sum = 0, power = 1;
  for (int k = 0; k < terms; ++k, power *= ratio) sum += power;
  return sum;
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

TEST(PathTracer, PathsNeedTheEnvironmentsShadowRaysAndTheCpu) {
  scene::Scene unshadowed = blobUnderWhite(1);
  unshadowed.environment->occlusion = false;
  EXPECT_THROW(renderOnCpu(unshadowed), std::invalid_argument);
  scene::Scene prefiltered = blobUnderWhite(1);
  prefiltered.environment->method = scene::IblMethod::Prefiltered;
  EXPECT_THROW(renderOnCpu(prefiltered), std::invalid_argument);
  try {
    render(blobUnderWhite(1), Backend::Gpu);
    FAIL() << "the GPU rendered paths";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("render on the CPU reference only for now (--backend cpu)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace facet
