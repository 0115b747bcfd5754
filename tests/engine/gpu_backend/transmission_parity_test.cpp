// Transmission and absorption on the GPU's paths (docs/rendering.md,
// "Transmission and absorption"): a clear glass ball in a uniform white
// environment renders the environment (the furnace), and glass, ruby and a
// thin absorbing wall trace the CPU reference's paths, ray for ray per
// bounce and per pixel, a limit on transmissions too; the public renderer
// renders them.
#include <glm/exponential.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>
#include <string>

#include "engine/gpu_backend/frame_params.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "engine/renderer.h"
#include "materials/material.h"
#include "scenes/environment_map.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/cages.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/gpu_device.h"
#include "tests/support/path_parity.h"
#include "tests/support/textured_gltf.h"

namespace facet {
namespace {

using testing::buildTestMaterial;
using testing::coveredMean;
using testing::glassSpec;
using testing::underWhite;

using GpuTransmission = testing::GpuRenderTest;

TEST_F(GpuTransmission, GlassBallInAWhiteFurnaceRendersTheEnvironment) {
  const materials::Material glass = buildTestMaterial(glassSpec(1.5));
  scene::Scene scene = underWhite(glass, testing::uvSphereCage(12, 24), 0, 12, 35);
  scene.render.samplesPerPixel = 4;
  const glm::dvec3 direct = coveredMean(render(scene).image);
  scene.render.bounces = 16;
  const glm::dvec3 paths = coveredMean(render(scene).image);
  std::printf("glass ball, white furnace: bounces 0 mean %.5f, bounces 16 mean %.5f %.5f %.5f\n", direct.x, paths.x,
              paths.y, paths.z);
  EXPECT_LT(direct.x, 0.2);  // reflection alone
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(paths[c], 1.0, 0.02);
}

// Energy compensation of glass: the GPU weighs a rough ball's reflections
// and transmissions by the glass tables the CPU reference reads, so it
// keeps all the light and traces the reference's paths.
TEST_F(GpuTransmission, ACompensatedRoughGlassBallTracesTheCpuReferencesPathsAndKeepsTheLight) {
  materials::MaterialSpec spec = glassSpec(1.5);
  spec.alpha = 0.36;
  spec.energyCompensation = true;
  scene::Scene scene = underWhite(buildTestMaterial(spec), testing::uvSphereCage(12, 24), 16, 12, 35);
  scene.render.samplesPerPixel = 64;  // at 16 the mean still moves by 5% with the seed
  const testing::PathRenders r = testing::renderBoth(device_, scene);
  const glm::dvec3 gpu = coveredMean(r.gpu.image), cpu = coveredMean(r.reference);
  std::printf("compensated rough glass ball, white furnace: GPU %.5f, CPU %.5f\n", gpu.x, cpu.x);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[c], 1.0, 0.02);
  testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-3, .parted = 3});
}

TEST_F(GpuTransmission, GlassAndRubyTraceTheCpuReferencesPaths) {
  const auto courtyard = std::make_shared<const scene::EnvironmentMap>(
      scene::loadEnvironmentMap(std::filesystem::path(FACET_ENVIRONMENTS_DIR) / "courtyard_256x128.hdr"));
  for (auto method : {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated}) {
    SCOPED_TRACE(method == scene::IntersectionMethod::Exact ? "exact" : "tessellated");
    scene::Scene scene = testing::glassAndRubyOnGround(courtyard, 4, 40, 24);
    scene.render.method = method;
    const testing::PathRenders r = testing::renderBoth(device_, scene);
    EXPECT_GT(r.cpuRays.raysPerBounce.at(2).hits, 100u);  // paths go through the balls
    // A path whose float and double parted (a hit at a silhouette, a Fresnel
    // choice against its number) moves its pixel by its share of the
    // pixel's samples, which through glass may see the sun: a few such
    // pixels, the others agree to float's precision.
    testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-3, .parted = 5});
  }
}

// A thin wall bends nothing and absorbs over its thickness: its
// continuation carries the Beer-Lambert factor itself, and the path's
// medium stays air.
TEST_F(GpuTransmission, AThinAbsorbingWallTracesTheCpuReferencesPaths) {
  materials::MaterialSpec spec = glassSpec(1.5);
  spec.alpha = 0.2;
  spec.thinWalled = true;
  spec.thickness = 0.5;
  spec.attenuationColor = glm::dvec3(0.9, 0.4, 0.2);
  spec.attenuationDistance = 1.0;
  scene::Scene scene = underWhite(
      buildTestMaterial(spec), scene::testing::singleFace({{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}}), 3, 12, 20);
  scene.render.samplesPerPixel = 4;
  testing::expectPathParity(testing::renderBoth(device_, scene),
                            {.median = 1e-5, .p98 = 1e-5, .parted = 0, .mean = 1e-5});
}

// A path leaves a transmissive surface from the vertex itself, keeping the
// solid's far side however near (docs/rendering.md, "Leaving a transmissive
// surface"): a slab of absorbing glass a sixth of the GPU's leaving offset
// thick traces the CPU reference's paths by either method and transmits as
// Airy's sum says. (Thinner than a few float ulps of its distance from the
// eye, a solid still has its far side found, but the float positions no
// longer resolve the path's length inside it.)
TEST_F(GpuTransmission, ASlabThinnerThanTheLeavingOffsetTracesTheCpuReferencesPaths) {
  const double depth = 2e-5;
  for (auto method : {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated}) {
    SCOPED_TRACE(method == scene::IntersectionMethod::Exact ? "exact" : "tessellated");
    materials::MaterialSpec spec = glassSpec(1.5);
    spec.attenuationColor = glm::dvec3(0.2, 0.5, 0.8);
    spec.attenuationDistance = depth;
    scene::Scene scene = underWhite(buildTestMaterial(spec), testing::slab(depth), 8, 12, 4);
    // The slab is not the scene's first object, so that its crossings must name it: a grey
    // speck out of every path's way comes first.
    materials::MaterialSpec grey;
    grey.name = "grey";
    grey.alpha = 0.5;
    grey.f0 = glm::dvec3(0.04);
    grey.diffuse = glm::dvec3(0.5);
    scene.materials.push_back(buildTestMaterial(grey));
    scene::ControlCage speck = testing::slab(1.0);
    for (glm::dvec3& p : speck.positions) p = 0.01 * p + glm::dvec3(2.5, 2.5, -1.0);
    scene.objects.insert(scene.objects.begin(), testing::testObject("speck", std::move(speck), 1));
    scene.render.method = method;
    scene.render.samplesPerPixel = 16;
    const scene::SceneGeometry geometry = scene::buildGeometry(scene);
    ASSERT_GT(rules::f64::shadow_ray_offset(geometry.bounds.diagonal(), gpu_backend::rootTolerance(scene, geometry)),
              5 * depth);
    const testing::PathRenders r = testing::renderBoth(device_, scene);
    testing::expectPathParity(r, {.median = 1e-2, .p98 = 2e-2, .mean = 1e-2});
    const glm::dvec3 gpu = coveredMean(r.gpu.image);
    const double f = rules::f64::fresnel_dielectric(1.5, 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[c], testing::slabUnderWhite(f, (*spec.attenuationColor)[c]), 1e-2) << c;
  }
}

// Beer-Lambert over the segment between two vertices, not from the ray's
// origin: the GPU's float offset grows with the scene's distance from the
// eye (32 2^-20 of it), and from 1000 units away it moved each refracted
// ray's origin 0.03 into a slab 2 thick, which then passed exp(0.03 sigma)
// too much light (4% where sigma is 1.4). The view keeps to the slab's
// middle.
TEST_F(GpuTransmission, AnAbsorbingSlabFarFromTheEyeAbsorbsAsTheCpuReferenceDoes) {
  materials::MaterialSpec spec = glassSpec(1.5);
  spec.attenuationColor = glm::dvec3(0.2, 0.5, 0.8);
  spec.attenuationDistance = 0.5;
  scene::ControlCage slab = scene::loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  for (glm::dvec3& p : slab.positions) p *= glm::dvec3(20.0, 20.0, 1.0);
  scene::Scene scene = underWhite(buildTestMaterial(spec), std::move(slab), 8, 16, 0.25);
  scene.camera.eye = glm::normalize(glm::dvec3(0.1, 0.2, 1.0)) * 1000.0;
  scene.render.samplesPerPixel = 4;
  const testing::PathRenders r = testing::renderBoth(device_, scene);
  const glm::dvec3 gpu = coveredMean(r.gpu.image), cpu = coveredMean(r.reference);
  std::printf("absorbing slab 1000 away: covered mean GPU %.5f %.5f %.5f, CPU %.5f %.5f %.5f\n", gpu.x, gpu.y, gpu.z,
              cpu.x, cpu.y, cpu.z);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[c] / cpu[c], 1.0, 2e-3) << c;
}

// The camera inside an absorbing solid (docs/rendering.md, "The camera
// inside a medium"): a sphere of radius 2 around the eye, in a uniform white
// environment. Of index 1 it bends and reflects nothing, so each camera
// ray leaves through the wall having crossed its distance d to it, and the
// image sums to what exp(-sigma d) does over its pixels, d the centre ray's
// depth; of index 1.5 its paths still trace the CPU reference's.
TEST_F(GpuTransmission, AnEyeInsideAnAbsorbingSolidSeesThroughIt) {
  materials::MaterialSpec spec = glassSpec(1.0);
  spec.attenuationColor = glm::dvec3(0.3, 0.6, 0.9);
  spec.attenuationDistance = 1.0;
  scene::ControlCage sphere = testing::uvSphereCage(24, 48);
  for (glm::dvec3& p : sphere.positions) p *= 2.0;
  scene::Scene scene = underWhite(buildTestMaterial(spec), std::move(sphere), 2, 16, 60);
  scene.camera.eye = {0.3, -0.2, 0.4};
  scene.render.samplesPerPixel = 4;
  const glm::dvec3 sigma = materials::transmissionParams64(scene.materials[0]).sigma;
  const testing::PathRenders clear = testing::renderBoth(device_, scene);
  for (const Image* image : {&clear.reference, &clear.gpu.image}) {
    SCOPED_TRACE(image == &clear.reference ? "CPU" : "GPU");
    glm::dvec3 rendered(0.0), expected(0.0);
    for (std::size_t i = 0; i < image->pixelCount(); ++i) {
      rendered += glm::dvec3(image->beauty[i]);
      expected += glm::exp(-sigma * double(image->depth[i]));
    }
    const glm::dvec3 ratio = rendered / expected;
    std::printf("eye inside absorbing glass of index 1: image sum / sum of exp(-sigma d) = %.5f %.5f %.5f\n", ratio.x,
                ratio.y, ratio.z);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.01) << c;
  }
  scene.materials[0] = buildTestMaterial([&] {
    materials::MaterialSpec refracting = spec;
    refracting.ior = glm::dvec3(1.5);
    return refracting;
  }());
  scene.render.bounces = 6;
  testing::expectPathParity(testing::renderBoth(device_, scene), {.median = 1e-4, .p98 = 2e-3, .parted = 5});
}

TEST_F(GpuTransmission, TheRendererRendersTransmissiveMaterialsOnTheGpu) {
  scene::Scene scene = underWhite(buildTestMaterial(glassSpec(1.5)), testing::uvSphereCage(8, 16), 2, 8, 35);
  scene.render.samplesPerPixel = 1;
  EXPECT_NO_THROW(facet::render(scene, Backend::Gpu));
  scene.render.transmissionBounces = 2;  // limits per lobe kind too
  EXPECT_NO_THROW(facet::render(scene, Backend::Gpu));
}

// glTF's transmission as its extension mixes it (docs/gltf.md): one texture
// makes a checker of glass (metallic 0) and metal (metallic 1, half the
// transmission factor, which the metal's share leaves unused) with mixed
// texels between them; the base colour tints what the glass transmits.
// Thin-walled, under a white sky, the wall traces the CPU reference's paths.
TEST_F(GpuTransmission, AGltfWallOfTexturedGlassAndMetalTracesTheCpuReferencesPaths) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("facet_gltf_glass_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  ASSERT_TRUE(testing::writePng(dir / "mask.png", 16, 16,
                                testing::checkerTexels(16, 4, {255, 77, 0, 255}, {128, 77, 255, 255})));
  const nlohmann::json material = {
      {"doubleSided", true},
      {"pbrMetallicRoughness",
       {{"baseColorFactor", {0.9, 0.6, 0.2, 1.0}}, {"metallicRoughnessTexture", {{"index", 0}}}}},
      {"extensions",
       {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}, {"transmissionTexture", {{"index", 0}}}}}}}};
  scene::Scene scene =
      scene::loadScene(testing::writeTexturedQuad(dir, "wall",
                                                  {{"materials", {material}},
                                                   {"textures", {{{"source", 0}}}},
                                                   {"images", {{{"uri", "mask.png"}}}},
                                                   {"extensionsUsed", {"KHR_materials_transmission"}}}));
  std::filesystem::remove_all(dir);
  const scene::Scene white = underWhite(scene.materials.at(0), testing::uvSphereCage(4, 8), 4, 16, 30);
  scene.camera = white.camera;
  scene.environment = white.environment;
  scene.render.width = scene.render.height = 16;
  scene.render.samplesPerPixel = 4;
  scene.render.bounces = 4;
  const testing::PathRenders r = testing::renderBoth(device_, scene);
  const glm::dvec3 mean = coveredMean(r.gpu.image);
  std::printf("glass and metal wall: covered mean %.5f %.5f %.5f\n", mean.x, mean.y, mean.z);
  EXPECT_GT(mean.x, 2 * mean.z);  // tinted
  testing::expectPathParity(r, {.median = 1e-5, .p98 = 1e-4, .worst = 1e-3, .parted = 0, .mean = 1e-5});
}

// Limits per lobe kind (docs/rendering.md, "Limits per lobe kind"): the
// environment seen through a glass ball takes two transmissions, in and
// out; with one the paths end inside it, where the CPU reference ends them.
TEST_F(GpuTransmission, ATransmissionLimitEndsPathsWhereTheCpuReferenceEndsThem) {
  const materials::Material glass = buildTestMaterial(glassSpec(1.5));
  for (int limit : {1, 2}) {
    SCOPED_TRACE("transmission bounces " + std::to_string(limit));
    scene::Scene scene = underWhite(glass, testing::uvSphereCage(12, 24), 8, 12, 35);
    scene.render.samplesPerPixel = 4;
    scene.render.transmissionBounces = limit;
    const testing::PathRenders r = testing::renderBoth(device_, scene);
    const double mean = coveredMean(r.gpu.image).x;
    std::printf("transmission bounces %d: covered mean %.5f\n", limit, mean);
    if (limit == 1)
      EXPECT_LT(mean, 0.2);  // reflection alone
    else
      EXPECT_GT(mean, 0.9);
    testing::expectSameRaysPerBounce(r);
    testing::expectPathParity(r, {.median = 1e-5, .p98 = 1e-4, .worst = 1e-3, .parted = 0, .mean = 1e-5});
  }
}

}  // namespace
}  // namespace facet
