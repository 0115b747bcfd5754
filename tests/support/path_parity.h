// A GPU render's paths against the CPU reference's of the same scene
// (docs/rendering.md, "Paths"): every bounce's rays, hits and shadow rays,
// up to the few that float and double send apart (a hit at a silhouette, a
// roulette or interface number against its probability), and the pixels, as
// tests/engine/gpu_backend/ibl_parity_test.cpp holds the sampled
// environment: percentiles of the relative error, the pixels whose paths
// parted, and the mean.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"
#include "tests/support/inside_sphere.h"
#include "tests/support/relative_errors.h"

namespace facet::testing {

// A GPU test that renders whole scenes.
class GpuRenderTest : public gpu::testing::GpuTest {
 protected:
  gpu_backend::GpuRenderResult render(const scene::Scene& scene) {
    gpu_backend::GpuRenderer renderer(device_);
    return renderer.render(scene, scene::buildGeometry(scene));
  }
};

// One scene rendered by both backends, with the CPU reference's ray counts.
struct PathRenders {
  Image reference;
  cpu::ReferenceStatistics cpuRays;
  gpu_backend::GpuRenderResult gpu;
};

inline PathRenders renderBoth(gpu::Device& device, const scene::Scene& scene) {
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  PathRenders r;
  r.reference = cpu::renderReference(scene, geometry, &r.cpuRays);
  gpu_backend::GpuRenderer renderer(device);
  r.gpu = renderer.render(scene, geometry);
  return r;
}

// A test's name per intersection method.
inline std::string methodName(const ::testing::TestParamInfo<scene::IntersectionMethod>& info) {
  return info.param == scene::IntersectionMethod::Exact ? "exact" : "tessellated";
}

struct PathParityBounds {
  double median, p98;
  double worst = std::numeric_limits<double>::infinity();
  std::size_t parted = std::numeric_limits<std::size_t>::max();  // pixels whose error exceeds 1e-2
  double mean = 2e-3;                                            // relative difference of the means
};

inline void expectPathParity(const PathRenders& r, const PathParityBounds& bounds) {
  const Image& reference = r.reference;
  const cpu::ReferenceStatistics& cpuRays = r.cpuRays;
  const gpu_backend::GpuRenderResult& gpu = r.gpu;
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
  const std::vector<double> errors = relativeErrors(reference, gpu.image);
  const double median = errors[errors.size() / 2], p98 = errors[errors.size() * 98 / 100], worst = errors.back();
  const auto parted = std::size_t(std::count_if(errors.begin(), errors.end(), [](double e) { return e > 1e-2; }));
  std::printf("relative error median %.2e, 98th percentile %.2e, max %.2e; %zu of %zu pixels above 1e-2\n", median, p98,
              worst, parted, errors.size());
  EXPECT_LT(median, bounds.median);
  EXPECT_LT(p98, bounds.p98);
  EXPECT_LT(worst, bounds.worst);
  EXPECT_LE(parted, bounds.parted);
  EXPECT_EQ(analysis::compareImages(reference, gpu.image).coverageMismatchesInterior, 0u);
  const double cpuMean = meanRadiance(reference).mean, gpuMean = meanRadiance(gpu.image).mean;
  std::printf("mean radiance: GPU %.6f, CPU %.6f, relative difference %.2e\n", gpuMean, cpuMean, gpuMean / cpuMean - 1);
  EXPECT_NEAR(gpuMean, cpuMean, bounds.mean * cpuMean);
}

// Every bounce's rays exactly as the CPU reference's, for scenes where no
// path's float and double part: each path ends on the GPU where it ends on
// the CPU.
inline void expectSameRaysPerBounce(const PathRenders& r) {
  ASSERT_EQ(r.gpu.raysPerBounce.size(), r.cpuRays.raysPerBounce.size());
  for (std::size_t b = 0; b < r.gpu.raysPerBounce.size(); ++b) {
    EXPECT_EQ(r.gpu.raysPerBounce[b].rays, r.cpuRays.raysPerBounce[b].rays) << "bounce " << b;
    EXPECT_EQ(r.gpu.raysPerBounce[b].hits, r.cpuRays.raysPerBounce[b].hits) << "bounce " << b;
  }
}

}  // namespace facet::testing
