// Paths on the GPU (docs/rendering.md, "Paths") against what is known
// exactly, the interreflection inside a closed diffuse sphere, and against
// the CPU reference, which traces the same paths in double: per pixel, and
// ray for ray per bounce, with limits per lobe kind too.
#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"
#include "tests/support/relative_errors.h"
#include "tests/support/inside_sphere.h"
#include "tests/support/path_parity.h"
#include "tests/support/preview_objects.h"

namespace facet {
namespace {

using testing::relativeErrors;

using testing::geometricSum;
using testing::insideDiffuseSphere;
using testing::meanRadiance;
using testing::previewWithPaths;

using GpuPaths = testing::GpuRenderTest;

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

// Limits per lobe kind (docs/rendering.md, "Limits per lobe kind"): a path
// ends where the CPU reference ends it, at the continuation that would
// exceed its kind's limit. Inside the closed sphere every path takes two
// diffuse continuations and no third, after roulette has drawn its number.
TEST_F(GpuPaths, ADiffuseLimitEndsPathsWhereTheCpuReferenceEndsThem) {
  scene::Scene limited = insideDiffuseSphere(0.5, 6, 16, 4);
  limited.render.diffuseBounces = 2;
  const testing::PathRenders r = testing::renderBoth(device_, limited);
  testing::expectSameRaysPerBounce(r);
  EXPECT_EQ(r.gpu.raysPerBounce.at(2).rays, r.gpu.raysPerBounce[1].rays);
  EXPECT_EQ(r.gpu.raysPerBounce.at(3).rays, 0u);
  testing::expectPathParity(r, {.median = 1e-5, .p98 = 1e-5, .worst = 1e-4, .parted = 0, .mean = 1e-5});
  // The limit ends the paths as two bounces would.
  const Image two = render(insideDiffuseSphere(0.5, 2, 16, 4)).image;
  for (std::size_t p = 0; p < two.pixelCount(); ++p) ASSERT_EQ(r.gpu.image.beauty[p], two.beauty[p]) << p;
}

class GpuPathParity : public GpuPaths, public ::testing::WithParamInterface<scene::IntersectionMethod> {};

TEST_P(GpuPathParity, TracesTheCpuReferencesPaths) {
  const testing::PathRenders r = testing::renderBoth(device_, previewWithPaths(GetParam(), 3));
  EXPECT_GT(r.cpuRays.raysPerBounce.at(1).hits, 20u);  // the objects light each other
  // The paths add the pixels where a continuation's hit or a roulette number
  // parts, each at most its share of the pixel's samples.
  testing::expectPathParity(r, {.median = 1e-4, .p98 = 5e-3, .worst = 0.5});
}

INSTANTIATE_TEST_SUITE_P(BothMethods, GpuPathParity,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         testing::methodName);

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
