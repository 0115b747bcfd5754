// Parity on real renders of both backends: they pass, and a GPU whose
// beauty is 5% too bright (a bias injected into its output) fails, judged by
// tolerance under prefiltered lighting and by the paired t-test under
// sampled lighting.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "analysis/parity.h"
#include "analysis/parity_statistics.h"
#include "engine/renderer.h"
#include "scenes/environment_map.h"
#include "scenes/scene_file.h"

namespace facet::analysis {
namespace {

scene::Scene goldCubeUnder(scene::IblMethod method) {
  scene::Scene s = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "gold_cube.gltf");
  s.render.width = 24;
  s.render.height = 16;
  s.lights.clear();
  s.environment.emplace();
  s.environment->map = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / "courtyard_256x128.hdr"));
  s.environment->method = method;
  s.environment->samples = 4;
  return s;
}

Image brighter(Image image) {
  for (glm::vec4& b : image.beauty) b = glm::vec4(glm::vec3(b) * 1.05f, b.a);
  return image;
}

TEST(ParityRenders, PrefilteredLightingPassesAndABiasFails) {
  const scene::Scene s = goldCubeUnder(scene::IblMethod::Prefiltered);
  Renderer renderer;
  const Image gpu = renderer.render(s, Backend::Gpu).image, cpu = renderer.render(s, Backend::Cpu).image;
  const ParityReport report = compareImages(cpu, gpu);
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_GT(report.covered, 50u);
  EXPECT_EQ(compareImages(cpu, brighter(gpu)).verdict, Verdict::Fail);
}

TEST(ParityRenders, SampledLightingPassesTheTTestAndABiasFails) {
  scene::Scene s = goldCubeUnder(scene::IblMethod::Sampled);
  Renderer renderer;
  PairedRenders pairs, biased;
  for (std::uint32_t seed = 0; seed < 16; ++seed) {  // --renders's default
    s.environment->seed = seed;
    const Image gpu = renderer.render(s, Backend::Gpu).image, cpu = renderer.render(s, Backend::Cpu).image;
    pairs.add(cpu, gpu);
    biased.add(cpu, brighter(gpu));
  }
  const ParityReport report = compareImages(pairs.referenceMean(), pairs.candidateMean(), {}, &pairs);
  EXPECT_TRUE(report.pass) << describe(report);
  EXPECT_EQ(report.aovs[2].test, "paired t-test");
  const ParityReport wrong = compareImages(biased.referenceMean(), biased.candidateMean(), {}, &biased);
  EXPECT_EQ(wrong.verdict, Verdict::Fail) << describe(wrong);
  EXPECT_GT(wrong.aovs[2].over(), wrong.covered / 2) << describe(wrong);
}

}  // namespace
}  // namespace facet::analysis
