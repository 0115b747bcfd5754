// Energy compensation in both renderers (engine/ibl/compensation_tables.h,
// docs/shading.md "Energy compensation"): the white furnace returns 1 with
// it for F(0) = 1 at every alpha and n.v >= 0.1, and loses energy without
// it; the GPU agrees with the CPU reference under punctual lights, where the
// factor is applied outside any environment method.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"

namespace facet {
namespace {

using scene::IblMethod;

// The preview's ten objects, each a perfect mirror colour (Schlick, F(0) = 1,
// no diffuse) of its own roughness from sqrt(alpha) = 0.1 to 1, under a
// white environment and nothing else.
scene::Scene furnace(IblMethod method, bool compensated) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json");
  s.lights.clear();
  s.render.width = 96;
  s.render.height = 48;
  // One camera sample, the one the AOVs describe: the n.v a pixel is
  // judged at is the n.v it was shaded at.
  s.render.samplesPerPixel = 1;
  s.render.method = scene::IntersectionMethod::Tessellated;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    materials::Material& m = s.materials[i];
    m.fresnel = rules::f64::F_SCHLICK;
    m.f0 = glm::dvec3(1.0);
    m.diffuse = glm::dvec3(0.0);
    const double roughness = double(i + 1) / double(s.materials.size());
    m.alpha = roughness * roughness;
    m.energyCompensation = compensated;
  }
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  s.environment->method = method;
  s.environment->occlusion = false;
  s.environment->samples = 256;
  return s;
}

// Over fully covered pixels whose shading normal faces the eye at n.v >= 0.1,
// per object (so per alpha): the mean of the furnace's radiance; and the
// largest distance of any such pixel from 1.
struct FurnaceResult {
  std::vector<double> objectMean;
  std::vector<double> objectAlpha;
  double worst = 0;
  std::size_t pixels = 0;
};

FurnaceResult measureFurnace(const scene::Scene& s, const Image& image) {
  std::vector<std::uint32_t> firstFace;
  std::uint32_t faces = 0;
  for (const scene::Object& object : s.objects) {
    firstFace.push_back(faces);
    faces += std::uint32_t(object.cage.faceCount());
  }
  FurnaceResult r;
  std::vector<double> sum(s.objects.size(), 0.0), count(s.objects.size(), 0.0);
  for (std::size_t i = 0; i < image.beauty.size(); ++i) {
    if (image.beauty[i].a != 1.0f) continue;
    const glm::dvec3 v = glm::normalize(s.camera.eye - glm::dvec3(image.position[i]));
    if (glm::dot(glm::dvec3(image.shadingNormal[i]), v) < 0.1) continue;
    const auto object =
        std::size_t(std::upper_bound(firstFace.begin(), firstFace.end(), image.faceId[i]) - firstFace.begin()) - 1;
    for (int c = 0; c < 3; ++c) {
      sum[object] += image.beauty[i][c] / 3.0;
      r.worst = std::max(r.worst, std::abs(double(image.beauty[i][c]) - 1.0));
    }
    count[object] += 1;
    ++r.pixels;
  }
  for (std::size_t k = 0; k < s.objects.size(); ++k) {
    if (count[k] < 20) continue;  // too few pixels to average out the noise
    r.objectMean.push_back(sum[k] / count[k]);
    r.objectAlpha.push_back(s.materials[std::size_t(s.objects[k].material)].alpha);
  }
  return r;
}

struct FurnaceCase {
  const char* name;
  bool gpu;
  IblMethod method;
};

class CompensatedFurnace : public gpu::testing::GpuTest, public ::testing::WithParamInterface<FurnaceCase> {
 protected:
  Image render(const scene::Scene& s) {
    const scene::SceneGeometry geometry = scene::buildGeometry(s);
    if (!GetParam().gpu) return cpu::renderReference(s, geometry);
    gpu_backend::GpuRenderer renderer(device_);
    return renderer.render(s, geometry).image;
  }
};

TEST_P(CompensatedFurnace, ReturnsOneWhereSingleScatteringLosesEnergy) {
  const IblMethod method = GetParam().method;
  const scene::Scene compensated = furnace(method, true), single = furnace(method, false);
  const FurnaceResult on = measureFurnace(compensated, render(compensated));
  const FurnaceResult off = measureFurnace(single, render(single));
  ASSERT_GT(on.pixels, 300u);
  ASSERT_GE(on.objectMean.size(), 8u);
  double lowest = 1;
  for (std::size_t k = 0; k < on.objectMean.size(); ++k) {
    std::printf("%s: alpha %.3f: compensated %.5f, single scattering %.4f\n", GetParam().name, on.objectAlpha[k],
                on.objectMean[k], off.objectMean[k]);
    EXPECT_NEAR(on.objectMean[k], 1.0, 1e-2) << "alpha " << on.objectAlpha[k];
    lowest = std::min(lowest, off.objectMean[k]);
  }
  std::printf("%s: worst pixel |L - 1| %.4f over %zu pixels\n", GetParam().name, on.worst, on.pixels);
  EXPECT_LT(lowest, 0.8);  // what the compensation restores at the roughest alpha
  // The split sum has no noise: every pixel is held to the 1%.
  // Monte Carlo pixels carry their estimator's noise around 1.
  EXPECT_LT(on.worst, method == IblMethod::Prefiltered ? 1e-2 : 0.2);
}

INSTANTIATE_TEST_SUITE_P(BackendsAndMethods, CompensatedFurnace,
                         ::testing::Values(FurnaceCase{"cpu_prefiltered", false, IblMethod::Prefiltered},
                                           FurnaceCase{"gpu_prefiltered", true, IblMethod::Prefiltered},
                                           FurnaceCase{"cpu_sampled", false, IblMethod::Sampled},
                                           FurnaceCase{"gpu_sampled", true, IblMethod::Sampled},
                                           FurnaceCase{"cpu_filtered", false, IblMethod::Filtered},
                                           FurnaceCase{"gpu_filtered", true, IblMethod::Filtered}),
                         [](const auto& info) { return std::string(info.param.name); });

class CompensatedLights : public gpu::testing::GpuTest {};

// The preview under its directional light alone, every material
// compensated: within parity, and brighter than without where the lobe is
// specular.
TEST_F(CompensatedLights, MatchTheReferenceAndBrightenTheSpecularLobe) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json");
  s.environment.reset();
  s.render.width = 96;
  s.render.height = 48;
  s.render.method = scene::IntersectionMethod::Tessellated;
  scene::Scene single = s;
  for (materials::Material& m : s.materials) m.energyCompensation = true;
  const scene::SceneGeometry geometry = scene::buildGeometry(s);
  const Image reference = cpu::renderReference(s, geometry);
  gpu_backend::GpuRenderer renderer(device_);
  const Image gpu = renderer.render(s, geometry).image;
  const analysis::ParityReport report = analysis::compareImages(reference, gpu);
  std::printf("%s", analysis::describe(report).c_str());
  EXPECT_TRUE(report.pass);

  const Image uncompensated = cpu::renderReference(single, geometry);
  std::size_t brighter = 0, darker = 0;
  for (std::size_t i = 0; i < reference.beauty.size(); ++i) {
    const float on = reference.beauty[i].r + reference.beauty[i].g + reference.beauty[i].b;
    const float off = uncompensated.beauty[i].r + uncompensated.beauty[i].g + uncompensated.beauty[i].b;
    brighter += on > off;
    darker += on < off;
  }
  EXPECT_GT(brighter, reference.beauty.size() / 20);
  EXPECT_EQ(darker, 0u);
}

}  // namespace
}  // namespace facet
