// Renderer::render's settings (api/render.cpp) through the public API alone:
// paths of bounces above 0 on both backends, and the settings the renderers refuse.
#include <gtest/gtest.h>

#include <facet/facet.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace {

// A cube on a slab under a sampled, shadowed environment: continuations from
// each find the other, so a bounce adds light that direct lighting lacks.
facet::Cage box(facet::Vec3 low, facet::Vec3 high) {
  facet::Cage cage;
  for (int i = 0; i < 8; ++i)
    cage.positions.push_back({i & 1 ? high.x : low.x, i & 2 ? high.y : low.y, i & 4 ? high.z : low.z});
  cage.faceVertexCounts = {4, 4, 4, 4, 4, 4};
  cage.faceVertexIndices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  return cage;
}

facet::Scene cubeOnSlab(facet::IblMethod method) {
  facet::SceneDescription description;  // no materials: grey plastic
  description.objects = {{"cube", box({-1, -1, -1}, {1, 1, 1}), 0, false},
                         {"slab", box({-4, -1.5, -4}, {4, -1, 4}), 0, false}};
  description.camera = facet::Camera{{3, 2.5, 4}, {0, -0.5, 0}, {0, 1, 0}, 50};
  facet::Environment environment;
  environment.file = std::string(FACET_ENVIRONMENTS_DIR) + "/courtyard_256x128.hdr";
  environment.method = method;
  environment.samples = 4;
  description.environment = environment;
  description.width = description.height = 16;
  return facet::buildScene(description);
}

// One pass of one sample per pixel: these tests count its rays.
facet::RenderSettings onCpu(int bounces) {
  facet::RenderSettings settings;
  settings.backend = facet::Backend::Cpu;
  settings.spp = 1;
  settings.bounces = bounces;
  return settings;
}

double sumOfBeauty(const facet::RenderResult& result) {
  const facet::Aov& beauty = result.image.aov("beauty");
  double sum = 0;
  for (std::size_t i = 0; i < beauty.values.size(); i += 4)
    sum += beauty.values[i] + beauty.values[i + 1] + beauty.values[i + 2];
  return sum;
}

std::string errorOf(facet::Renderer& renderer, const facet::Scene& scene, const facet::RenderSettings& settings) {
  try {
    renderer.render(scene, settings);
  } catch (const facet::Error& e) {
    EXPECT_EQ(e.kind(), facet::ErrorKind::BadInput);
    return e.what();
  }
  return "no error";
}

TEST(ApiRender, OneBounceAddsTheLightBetweenObjectsAndCountsItsRays) {
  facet::Renderer renderer;
  const facet::Scene scene = cubeOnSlab(facet::IblMethod::Sampled);
  const facet::RenderResult direct = renderer.render(scene, onCpu(0));
  const facet::RenderResult paths = renderer.render(scene, onCpu(1));
  EXPECT_TRUE(direct.raysPerBounce.empty());
  ASSERT_EQ(paths.raysPerBounce.size(), 2u);
  EXPECT_EQ(paths.raysPerBounce[0].rays, 16u * 16u);  // one camera ray per pixel at 1 spp
  EXPECT_GT(paths.raysPerBounce[1].hits, 0u);
  EXPECT_GT(sumOfBeauty(paths), sumOfBeauty(direct));
}

TEST(ApiRender, BouncesAreCheckedAsTheSceneFileChecksThem) {
  facet::Renderer renderer;
  const facet::Scene sampled = cubeOnSlab(facet::IblMethod::Sampled);
  EXPECT_EQ(errorOf(renderer, sampled, onCpu(65)), "render settings: bounces: must be in [0, 64]");
  EXPECT_EQ(errorOf(renderer, sampled, onCpu(-1)), "render settings: bounces: must be in [0, 64]");
  // The split sum counts the environment unshadowed at every vertex: paths would count it twice.
  const std::string prefiltered = errorOf(renderer, cubeOnSlab(facet::IblMethod::Prefiltered), onCpu(1));
  EXPECT_EQ(
      prefiltered.rfind("render settings: bounces: bounces above 0 need the environment lit with its shadow rays", 0),
      0u)
      << prefiltered;
}

// Unsaid bounces are chosen from the scene as `facet render` chooses them
// (docs/rendering.md, "Light transport chosen by the scene").
TEST(ApiRender, UnsaidBouncesAreChosenFromTheScene) {
  facet::Renderer renderer;
  facet::RenderSettings settings;
  settings.backend = facet::Backend::Cpu;
  const facet::RenderResult chosen = renderer.render(cubeOnSlab(facet::IblMethod::Sampled), settings);
  EXPECT_EQ(chosen.bounces, 12);
  EXPECT_EQ(chosen.lightTransport,
            "paths: 12 bounces (diffuse 4, glossy 4, transmission 12): 2 objects can see each other");
  ASSERT_GT(chosen.raysPerBounce.size(), 1u);
  EXPECT_GT(chosen.raysPerBounce[1].hits, 0u);
  // Nor is the sampling said: adaptive rounds, reported as `facet render` reports them.
  const facet::SamplingReport& rounds = chosen.sampling;
  EXPECT_EQ(rounds.spp, 0);
  EXPECT_GE(rounds.rounds, 4);
  EXPECT_LE(rounds.sppMin, rounds.sppMean);
  EXPECT_LE(rounds.sppMean, rounds.sppMax);
  EXPECT_EQ(rounds.noiseThreshold, 0.02);
  if (rounds.stop == "converged")
    EXPECT_LE(rounds.maxTileError, rounds.noiseThreshold);
  else
    EXPECT_EQ(rounds.stop, "sample cap");
  EXPECT_EQ(rounds.why, "paths and the environment's samples are random");
  const facet::RenderResult stated = renderer.render(cubeOnSlab(facet::IblMethod::Sampled), onCpu(0));
  EXPECT_EQ(stated.bounces, 0);
  EXPECT_TRUE(stated.lightTransport.empty());
  EXPECT_EQ(stated.sampling.spp, 1);
  EXPECT_EQ(stated.sampling.rounds, 0);
  EXPECT_TRUE(stated.sampling.why.empty());
}

TEST(ApiRender, TheGpuTracesTheCpusPathsRayForRay) {
  facet::Renderer renderer;
  const facet::Scene scene = cubeOnSlab(facet::IblMethod::Sampled);
  facet::RenderSettings settings = onCpu(1);
  const facet::RenderResult cpu = renderer.render(scene, settings);
  settings.backend = facet::Backend::Gpu;
  const facet::RenderResult gpu = renderer.render(scene, settings);
  ASSERT_EQ(gpu.raysPerBounce.size(), 2u);
  EXPECT_EQ(gpu.raysPerBounce[0].rays, cpu.raysPerBounce[0].rays);
  EXPECT_EQ(gpu.raysPerBounce[1].rays, cpu.raysPerBounce[1].rays);
  EXPECT_GT(gpu.raysPerBounce[1].hits, 0u);
}

TEST(ApiRender, ParityComparesPaths) {
  facet::Renderer renderer;
  const facet::ParityReport report = renderer.parity(cubeOnSlab(facet::IblMethod::Sampled), onCpu(1));
  EXPECT_GT(report.covered, 0u);
  EXPECT_FALSE(report.summary.empty());
}

// A transparent preset transmits through the API as in a scene file; its
// transmission fields are checked alike, and the GPU refuses it.
TEST(ApiRender, TransparentPresetsTransmitOnBothBackends) {
  auto cubeOf = [](const facet::Material& material) {
    facet::SceneDescription description;
    description.materials = {material};
    description.objects = {{"cube", box({-1, -1, -1}, {1, 1, 1}), 0, false}};
    description.camera =
        facet::Camera{{3, -2.5, 4}, {0, 0, 0}, {0, 1, 0}, 50};  // reflecting the ground, seeing the sky
    facet::Environment environment;
    environment.file = std::string(FACET_ENVIRONMENTS_DIR) + "/courtyard_256x128.hdr";
    environment.method = facet::IblMethod::Sampled;
    environment.samples = 2;
    description.environment = environment;
    description.width = description.height = 16;
    return facet::buildScene(description);
  };
  facet::Material water;
  water.preset = "water";
  water.roughness = 0.0;
  facet::Material opaque = water;
  opaque.transmission = 0.0;
  facet::Renderer renderer;
  // Continuations through the cube add the environment behind it, which
  // the opaque cube (convex: its continuations find nothing) cannot.
  const facet::RenderResult through = renderer.render(cubeOf(water), onCpu(4));
  const facet::RenderResult reflectedOnly = renderer.render(cubeOf(water), onCpu(0));
  const std::vector<float>& after = through.image.aov("beauty").values;
  const std::vector<float>& before = reflectedOnly.image.aov("beauty").values;
  int brighter = 0;
  for (std::size_t i = 0; i < after.size(); i += 4) brighter += after[i] > before[i] + 0.05f;
  EXPECT_GT(brighter, 20);  // of the cube's ~65 pixels
  EXPECT_EQ(sumOfBeauty(renderer.render(cubeOf(opaque), onCpu(4))),
            sumOfBeauty(renderer.render(cubeOf(opaque), onCpu(0))));
  facet::RenderSettings gpu = onCpu(4);
  gpu.backend = facet::Backend::Gpu;  // the same paths, in float
  EXPECT_NEAR(sumOfBeauty(renderer.render(cubeOf(water), gpu)) / sumOfBeauty(through), 1.0, 0.01);
  facet::Material absorbing = water;
  absorbing.attenuationDistance = -1.0;
  try {
    cubeOf(absorbing);
    FAIL() << "a negative attenuation distance was accepted";
  } catch (const facet::Error& e) {
    EXPECT_EQ(e.kind(), facet::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("attenuation_distance: must be > 0"), std::string::npos) << e.what();
  }
}

// The API holds a render to the memory limit the CLI holds it to
// (engine/image_memory.h), before anything is allocated for it.
TEST(ApiRender, ARenderOverTheMemoryLimitIsRefusedAsOnTheCommandLine) {
  ASSERT_EQ(setenv("FACET_MEMORY_LIMIT", "64", 1), 0);
  facet::Renderer renderer;
  facet::RenderSettings large = onCpu(0);
  large.width = large.height = 2048;
  const std::string error = errorOf(renderer, cubeOnSlab(facet::IblMethod::Sampled), large);
  unsetenv("FACET_MEMORY_LIMIT");
  EXPECT_NE(error.find("the render needs about 0.4 GB of memory and the limit is 0.1 GB (FACET_MEMORY_LIMIT)"),
            std::string::npos)
      << error;
}

}  // namespace
