// Image-based lighting on the GPU held to the CPU reference: the three
// methods, the sampled and filtered ones with and without shadow rays, the
// split sum's irradiance map and the filtered method's environment
// technique under the sunrise, drawing the same random numbers (rules/sampling/random.h). Tolerances in
// docs/rendering.md.
#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "analysis/parity.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"
#include "tests/support/relative_errors.h"

namespace facet {
namespace {

using testing::relativeErrors;

using analysis::compareImages;

using scene::IblMethod;

struct IblCase {
  const char* name;
  IblMethod method;
  bool occlusion;
  int samples;
  const char* map = "courtyard_256x128.hdr";
  bool compensated = false;  // energy compensation on every material
};

void PrintTo(const IblCase& c, std::ostream* out) { *out << c.name; }

// The default preview, lit by the case's map alone, small.
scene::Scene previewUnder(const IblCase& c) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json");
  s.lights.clear();
  s.render.width = 64;
  s.render.height = 32;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / c.map));
  s.environment->rotationDegrees = 40;
  s.environment->method = c.method;
  s.environment->occlusion = c.occlusion;
  s.environment->samples = c.samples;
  for (materials::Material& m : s.materials) m.energyCompensation = c.compensated;
  return s;
}

class IblParity : public gpu::testing::GpuTest, public ::testing::WithParamInterface<IblCase> {};

TEST_P(IblParity, MatchesTheCpuReference) {
  const scene::Scene s = previewUnder(GetParam());
  const scene::SceneGeometry geometry = scene::buildGeometry(s);
  cpu::ReferenceStatistics cpuRays;
  const Image reference = cpu::renderReference(s, geometry, &cpuRays);
  gpu_backend::GpuRenderer renderer(device_);
  const gpu_backend::GpuRenderResult gpu = renderer.render(s, geometry);

  const std::vector<double> errors = relativeErrors(reference, gpu.image);
  const double median = errors[errors.size() / 2], p99 = errors[errors.size() * 99 / 100], worst = errors.back();
  std::printf("%s: relative error median %.2e, 99th percentile %.2e, max %.2e; shadow rays cpu %llu gpu %llu\n",
              GetParam().name, median, p99, worst, (unsigned long long)cpuRays.shadowRays,
              (unsigned long long)gpu.shadowRays);
  EXPECT_LT(median, 1e-4);
  EXPECT_LT(p99, 2e-3);
  EXPECT_LT(worst, 2e-2);
  EXPECT_EQ(compareImages(reference, gpu.image).coverageMismatchesInterior, 0u);
  EXPECT_NEAR(double(gpu.shadowRays), double(cpuRays.shadowRays), 1e-2 * double(cpuRays.shadowRays) + 2);
}

INSTANTIATE_TEST_SUITE_P(
    Methods, IblParity,
    ::testing::Values(IblCase{"prefiltered", IblMethod::Prefiltered, false, 1},
                      IblCase{"prefiltered_sun", IblMethod::Prefiltered, false, 1, "sunrise.exr"},
                      IblCase{"sampled_unoccluded", IblMethod::Sampled, false, 8},
                      IblCase{"sampled_occluded", IblMethod::Sampled, true, 4},
                      IblCase{"filtered_unoccluded", IblMethod::Filtered, false, 8},
                      IblCase{"filtered_occluded", IblMethod::Filtered, true, 4},
                      IblCase{"filtered_sun_occluded", IblMethod::Filtered, true, 4, "sunrise.exr"},
                      IblCase{"prefiltered_compensated", IblMethod::Prefiltered, false, 1, "courtyard_256x128.hdr",
                              true},
                      IblCase{"sampled_compensated", IblMethod::Sampled, true, 4, "courtyard_256x128.hdr", true},
                      IblCase{"filtered_sun_compensated", IblMethod::Filtered, false, 8, "sunrise.exr", true}),
    [](const auto& info) { return std::string(info.param.name); });

// Under a white environment a white Lambert surface returns 1 with the split
// sum: the GPU's SH projection is exact too.
class IblFurnaceOnGpu : public gpu::testing::GpuTest {};

TEST_F(IblFurnaceOnGpu, PrefilteredWhiteLambertReturnsOne) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  s.lights.clear();
  s.materials[0].fresnel = rules::f64::F_DIELECTRIC;  // index 1: no specular lobe at all
  s.materials[0].eta = glm::dvec3(1.0);
  s.materials[0].diffuse = glm::dvec3(1.0);
  s.render.width = s.render.height = 24;
  s.render.method = scene::IntersectionMethod::Tessellated;
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  gpu_backend::GpuRenderer renderer(device_);
  const Image image = renderer.render(s, scene::buildGeometry(s)).image;
  int covered = 0;
  for (const glm::vec4& b : image.beauty) {
    covered += b.a == 1.0f;
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(b[c], 1.0f, 1e-5f);
  }
  EXPECT_GT(covered, 50);
}

}  // namespace
}  // namespace facet
