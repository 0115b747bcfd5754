// Paths on the GPU (docs/rendering.md, "Paths") against what is known
// exactly, the interreflection inside a closed diffuse sphere, and against
// the CPU reference, which traces the same paths in double: per pixel, and
// ray for ray per bounce.
#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/environment_map.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"
#include "tests/support/relative_errors.h"
#include "tests/support/inside_sphere.h"

namespace facet {
namespace {

using testing::relativeErrors;

using testing::geometricSum;
using testing::insideDiffuseSphere;
using testing::meanRadiance;

class GpuPaths : public gpu::testing::GpuTest {
 protected:
  gpu_backend::GpuRenderResult render(const scene::Scene& scene) {
    gpu_backend::GpuRenderer renderer(device_);
    return renderer.render(scene, scene::buildGeometry(scene));
  }
};

TEST_F(GpuPaths, InsideADiffuseSphereEachBounceAddsTheAlbedoTimesTheLast) {
  const double albedo = 0.5;
  const double direct = meanRadiance(render(insideDiffuseSphere(albedo, 0, 24, 4)).image).mean;
  EXPECT_NEAR(direct, albedo, 0.01 * albedo);  // L0 = rho, to the polygon sphere's flatness
  for (int bounces : {1, 2}) {
    const double mean = meanRadiance(render(insideDiffuseSphere(albedo, bounces, 24, 4)).image).mean;
    const double expected = direct * geometricSum(albedo, bounces + 1);
    std::printf("bounces %d: mean %.5f, L0 sum %.5f, relative error %.2e\n", bounces, mean, expected,
                mean / expected - 1);
    EXPECT_NEAR(mean, expected, 0.015 * expected) << bounces << " bounces";
  }
}

TEST_F(GpuPaths, RussianRouletteKeepsTheMean) {
  const double albedo = 0.8;
  const int bounces = 8;
  const gpu_backend::GpuRenderResult r = render(insideDiffuseSphere(albedo, bounces, 24, 4));
  ASSERT_EQ(r.raysPerBounce.size(), std::size_t(bounces) + 1);
  EXPECT_EQ(r.raysPerBounce[2].rays, r.raysPerBounce[1].rays);  // the sphere is closed: no path ends before roulette
  EXPECT_LT(double(r.raysPerBounce[3].rays), 0.9 * double(r.raysPerBounce[2].rays));
  // Without roulette each throughput is exactly rho^k: the mean is L0 (1 + ... + rho^N).
  const testing::PixelMean mean = meanRadiance(r.image);
  const double expected = albedo * geometricSum(albedo, bounces + 1);
  std::printf("roulette: mean %.5f +- %.5f, without roulette %.5f\n", mean.mean, mean.standardError, expected);
  EXPECT_NEAR(mean.mean, expected, 4 * mean.standardError + 0.01 * expected);
}

// The preview's objects, close enough to light each other, under the
// courtyard with its shadow rays, small.
scene::Scene previewWithPaths(scene::IntersectionMethod method, int bounces) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json");
  s.lights.clear();
  s.render.width = 48;
  s.render.height = 24;
  s.render.method = method;
  s.render.bounces = bounces;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / "courtyard_256x128.hdr"));
  s.environment->method = scene::IblMethod::Sampled;
  s.environment->occlusion = true;
  s.environment->samples = 2;
  return s;
}

class GpuPathParity : public GpuPaths, public ::testing::WithParamInterface<scene::IntersectionMethod> {};

TEST_P(GpuPathParity, TracesTheCpuReferencesPaths) {
  const scene::Scene scene = previewWithPaths(GetParam(), 3);
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  cpu::ReferenceStatistics cpuRays;
  const Image reference = cpu::renderReference(scene, geometry, &cpuRays);
  gpu_backend::GpuRenderer renderer(device_);
  const gpu_backend::GpuRenderResult gpu = renderer.render(scene, geometry);

  // The same paths: every bounce's rays, hits and shadow rays, up to the few
  // that float and double send apart (a hit at a silhouette, a roulette
  // number against a throughput).
  ASSERT_EQ(gpu.raysPerBounce.size(), cpuRays.raysPerBounce.size());
  for (std::size_t b = 0; b < gpu.raysPerBounce.size(); ++b) {
    const cpu::BounceRays& c = cpuRays.raysPerBounce[b];
    const gpu_backend::GpuBounceRays& g = gpu.raysPerBounce[b];
    std::printf("bounce %zu: rays %llu / %llu, hits %llu / %llu, shadow %llu / %llu (GPU / CPU)\n", b,
                (unsigned long long)g.rays, (unsigned long long)c.rays, (unsigned long long)g.hits,
                (unsigned long long)c.hits, (unsigned long long)g.shadowRays, (unsigned long long)c.shadowRays);
    EXPECT_NEAR(double(g.rays), double(c.rays), 0.01 * double(c.rays) + 2) << "bounce " << b;
    EXPECT_NEAR(double(g.hits), double(c.hits), 0.01 * double(c.hits) + 2) << "bounce " << b;
    EXPECT_NEAR(double(g.shadowRays), double(c.shadowRays), 0.01 * double(c.shadowRays) + 4) << "bounce " << b;
  }
  EXPECT_GT(cpuRays.raysPerBounce.at(1).hits, 20u);  // the objects light each other

  // Per pixel, as tests/engine/gpu_backend/ibl_parity_test.cpp holds the
  // sampled environment (whose float and double numbers part now and then):
  // the paths add the pixels where a continuation's hit or a roulette number
  // parts, each at most its share of the pixel's samples.
  const std::vector<double> errors = relativeErrors(reference, gpu.image);
  const double median = errors[errors.size() / 2], p98 = errors[errors.size() * 98 / 100], worst = errors.back();
  std::printf("relative error median %.2e, 98th percentile %.2e, max %.2e\n", median, p98, worst);
  EXPECT_LT(median, 1e-4);
  EXPECT_LT(p98, 5e-3);
  EXPECT_LT(worst, 0.5);
  EXPECT_EQ(analysis::compareImages(reference, gpu.image).coverageMismatchesInterior, 0u);
  const double cpuMean = meanRadiance(reference).mean, gpuMean = meanRadiance(gpu.image).mean;
  std::printf("mean radiance: GPU %.6f, CPU %.6f, relative difference %.2e\n", gpuMean, cpuMean, gpuMean / cpuMean - 1);
  EXPECT_NEAR(gpuMean, cpuMean, 2e-3 * cpuMean);
}

INSTANTIATE_TEST_SUITE_P(BothMethods, GpuPathParity,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         [](const ::testing::TestParamInfo<scene::IntersectionMethod>& info) {
                           return info.param == scene::IntersectionMethod::Exact ? "exact" : "tessellated";
                         });

// A crop's paths draw the numbers of the full image's pixels, so its pixels
// are the whole render's, bit for bit.
TEST_F(GpuPaths, ACropTracesTheWholeRendersPaths) {
  const scene::Scene scene = previewWithPaths(scene::IntersectionMethod::Tessellated, 2);
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  gpu_backend::GpuRenderer renderer(device_);
  const Image whole = renderer.render(scene, geometry).image;
  const PixelRect window{13, 5, 37, 19};
  const Image crop = renderer.render(scene, geometry, {}, window).image;
  for (int y = window.y0; y < window.y1; ++y)
    for (int x = window.x0; x < window.x1; ++x)
      ASSERT_EQ(crop.beauty[crop.index(x - window.x0, y - window.y0)], whole.beauty[whole.index(x, y)])
          << x << ", " << y;
}

}  // namespace
}  // namespace facet
