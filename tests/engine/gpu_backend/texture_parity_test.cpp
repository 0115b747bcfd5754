// Textured glTF on both backends: a quad with a base-colour checker, a
// metallic-roughness ramp, a normal map, occlusion and emission, seen at 60
// degrees so that the ray cone picks mip levels across the image, within the
// tolerances of analysis/parity.h (beauty 1e-3 relative on 99.9% of covered
// pixels), under its key light and under a white environment (occlusion);
// and a JSON scene's c_diff and roughness textures on a subdivided cage; and
// a renderer that keeps its textures' upload still shows each scene's own.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "rules/rules.h"
#include "scenes/environment_map.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/gpu_device.h"
#include "tests/support/textured_scenes.h"

namespace facet {
namespace {

struct TextureCase {
  scene::IntersectionMethod method;
  bool environment;
  bool jsonCube = false;  // the JSON scene below instead of the glTF quad
};

// A JSON scene of the subdivided checker cube (face-varying texture
// coordinates) whose material maps c_diff to a checker and the roughness to
// a ramp.
std::filesystem::path writeJsonCheckerCube(const std::filesystem::path& dir) {
  std::filesystem::copy_file(std::filesystem::path(FACET_TEST_DATA_DIR) / "uv_checker_cube.obj", dir / "cube.obj");
  facet::testing::writePng(dir / "checker.png", 64, 64,
                           facet::testing::checkerTexels(64, 8, {230, 200, 40, 255}, {20, 60, 180, 255}));
  // The ramp's roughness (G) as a grey image: roughness textures read the first channel.
  std::vector<facet::testing::Rgba8> roughness = facet::testing::metallicRoughnessRamp();
  for (facet::testing::Rgba8& texel : roughness) texel.r = texel.b = texel.g;
  facet::testing::writePng(dir / "roughness.png", 64, 64, roughness);
  std::ofstream(dir / "scene.json") << R"({
    "objects": [{"mesh": "cube.obj", "material": {
      "diffuse_texture": {"image": "checker.png", "wrap": "mirror"}, "roughness_texture": "roughness.png",
      "fresnel": "schlick", "f0": 0.04}}],
    "camera": {"eye": [1.6, 1.3, 2.1], "target": [0, 0, 0]}})";
  return dir / "scene.json";
}

// A uniform white sky, sampled without occlusion: the same random numbers on
// both backends.
void underWhiteSky(scene::Scene& scene) {
  scene.environment.emplace();
  scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  scene.environment->method = scene::IblMethod::Sampled;
  scene.environment->occlusion = false;
  scene.environment->samples = 4;
}

// The GPU's image of `scene` within parity of the CPU reference's, which
// must differ on most covered pixels from the image of `without`, the scene
// without the textures under test: parity of images that ignore the
// textures would prove nothing.
void expectTexturesRenderAsOnTheCpu(gpu::Device& device, const scene::Scene& scene, const scene::Scene& without) {
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const Image reference = cpu::renderReference(scene, geometry);
  gpu_backend::GpuRenderer renderer(device);
  const analysis::ParityReport parity = analysis::compareImages(reference, renderer.render(scene, geometry).image);
  EXPECT_TRUE(parity.pass) << analysis::describe(parity);
  EXPECT_GT(parity.covered, 1000u);
  const Image untextured = cpu::renderReference(without, geometry);
  std::size_t differing = 0;
  for (std::size_t p = 0; p < reference.beauty.size(); ++p)
    if (glm::length(reference.beauty[p] - untextured.beauty[p]) > 0.05f * glm::length(untextured.beauty[p]))
      ++differing;
  EXPECT_GT(differing, parity.covered / 2);
}

// expectTexturesRenderAsOnTheCpu for the slots of the first material:
// without them is with those slots empty.
void expectSlotsRenderAsOnTheCpu(gpu::Device& device, const scene::Scene& scene,
                                 std::initializer_list<materials::TextureSlot materials::MaterialTextures::*> slots) {
  ASSERT_TRUE(scene.materials[0].textures.has_value());
  scene::Scene without = scene;
  for (auto slot : slots) (*without.materials[0].textures).*slot = {};
  expectTexturesRenderAsOnTheCpu(device, scene, without);
}

// How far the mean of the CPU reference's image of `b` over the covered
// pixels is from that of `a`, relative to it. The mean, not each pixel: a
// change of the lobes' weights changes which lobe a sample draws, so
// pixels part by their noise even where the estimate is the same.
double meanReferenceDifference(const scene::Scene& a, const scene::Scene& b) {
  const Image x = cpu::renderReference(a, scene::buildGeometry(a)),
              y = cpu::renderReference(b, scene::buildGeometry(b));
  glm::dvec3 sumX(0.0), sumY(0.0);
  for (std::size_t p = 0; p < x.beauty.size(); ++p)
    if (x.beauty[p].a != 0.0f) sumX += glm::dvec3(x.beauty[p]), sumY += glm::dvec3(y.beauty[p]);
  return glm::length(sumY - sumX) / glm::length(sumX);
}

// The CPU reference's mean of `textured` within `within` of that of `same`,
// a material whose factors say what the texture should have, and more than
// `apart` from that of `other`, what a wrong channel would give.
void expectMeanAsTheFactorsSay(const char* what, const scene::Scene& textured, const scene::Scene& same,
                               const scene::Scene& other, double within, double apart) {
  const double toSame = meanReferenceDifference(textured, same), toOther = meanReferenceDifference(textured, other);
  std::printf("%s: %.2e from the factors that say the same, %.2e from the others\n", what, toSame, toOther);
  EXPECT_LT(toSame, within);
  EXPECT_GT(toOther, apart);
}

class TextureParity : public gpu::testing::GpuTest, public ::testing::WithParamInterface<TextureCase> {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    dir_ = std::filesystem::temp_directory_path() / ("facet_texture_parity_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::filesystem::remove_all(dir_);
    GpuTest::TearDown();
  }
  std::filesystem::path dir_;
};

TEST_P(TextureParity, MatchesTheCpuReferenceWithinTolerance) {
  // glTF's LINEAR_MIPMAP_LINEAR: continuous in the coordinates and the level.
  scene::Scene scene =
      scene::loadScene(GetParam().jsonCube ? writeJsonCheckerCube(dir_)
                                           : facet::testing::writeTexturedScene(dir_, "quad", 8, 2.0, 9987));
  ASSERT_EQ(scene.textures.size(), GetParam().jsonCube ? 2u : 3u);
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.method = GetParam().method;
  if (GetParam().environment) underWhiteSky(scene);
  scene::Scene untextured = scene;
  untextured.materials[0].textures.reset();
  expectTexturesRenderAsOnTheCpu(device_, scene, untextured);
}

// The oblique quad of a dark, fairly smooth dielectric with glTF material
// `extensions`, whose slots read `checker`, a 16² checker of the two
// texels, under a white sky at 64 x 48, where the specular lobe shows what
// its textures do.
scene::Scene darkQuadUnderWhiteSky(const std::filesystem::path& dir, const std::string& name,
                                   const std::pair<facet::testing::Rgba8, facet::testing::Rgba8>& checker,
                                   const nlohmann::json& extensions) {
  facet::testing::writePng(dir / (name + ".png"), 16, 16,
                           facet::testing::checkerTexels(16, 4, checker.first, checker.second));
  nlohmann::json parts = facet::testing::obliqueCamera(30.0);
  parts["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorFactor", {0.05, 0.05, 0.05, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.3}}},
       {"extensions", extensions}}};
  parts["textures"] = {{{"source", 0}}};
  parts["images"] = {{{"uri", name + ".png"}}};
  scene::Scene scene = scene::loadScene(facet::testing::writeTexturedQuad(dir, name, parts));
  EXPECT_TRUE(scene.materials[0].textures.has_value());
  scene.render.width = 64;
  scene.render.height = 48;
  underWhiteSky(scene);
  return scene;
}

// KHR_materials_specular's textures and KHR_materials_ior on a textured
// dielectric: its F(0) per hit (dielectric_specular_f0); the same image on
// both backends, and not the image without the two textures.
TEST_F(TextureParity, SpecularTexturesGiveTheDielectricsF0AsOnTheCpu) {
  const scene::Scene scene = darkQuadUnderWhiteSky(dir_, "specular", {{255, 64, 0, 255}, {0, 128, 255, 40}},
                                                   {{"KHR_materials_ior", {{"ior", 2.0}}},
                                                    {"KHR_materials_specular",
                                                     {{"specularColorFactor", {2.0, 2.0, 2.0}},
                                                      {"specularTexture", {{"index", 0}}},
                                                      {"specularColorTexture", {{"index", 0}}}}}});
  expectSlotsRenderAsOnTheCpu(
      device_, scene,
      {&materials::MaterialTextures::specularTexture, &materials::MaterialTextures::specularColorTexture});
}

// KHR_materials_iridescence's textures: a checker whose R scales the film
// and whose G places its thickness between 100 and 700 nm; the same image on
// both backends, and not the image of the film's factors alone.
TEST_F(TextureParity, FilmTexturesPlaceItsStrengthAndThicknessAsOnTheCpu) {
  const nlohmann::json film = {{"KHR_materials_iridescence",
                                {{"iridescenceFactor", 1.0},
                                 {"iridescenceIor", 1.8},
                                 {"iridescenceThicknessMinimum", 100.0},
                                 {"iridescenceThicknessMaximum", 700.0},
                                 {"iridescenceTexture", {{"index", 0}}},
                                 {"iridescenceThicknessTexture", {{"index", 0}}}}}};
  const scene::Scene scene = darkQuadUnderWhiteSky(dir_, "film", {{255, 40, 0, 255}, {90, 230, 0, 255}}, film);
  expectSlotsRenderAsOnTheCpu(
      device_, scene,
      {&materials::MaterialTextures::iridescenceTexture, &materials::MaterialTextures::iridescenceThicknessTexture});
  // The channels: where R is 1 and G is 0 the film is the factor's at the
  // minimum, the material's own film of thickness 100 without textures.
  const scene::Scene uniform = darkQuadUnderWhiteSky(dir_, "uniform", {{255, 0, 0, 255}, {255, 0, 0, 255}}, film);
  scene::Scene thinnest = uniform;
  thinnest.materials[0].iridescenceThickness = 100.0;
  thinnest.materials[0].textures->iridescenceTexture = {};
  thinnest.materials[0].textures->iridescenceThicknessTexture = {};
  scene::Scene thickest = thinnest;
  thickest.materials[0].iridescenceThickness = 700.0;
  expectMeanAsTheFactorsSay("film", uniform, thinnest, thickest, 1e-9, 0.05);
}

// KHR_materials_sheen's roughness texture: a checker whose A sets the
// sheen's roughness to 0.16 and 0.55 of a factor of 1, its albedo knots
// read between the rows on both backends; the same image on both, and not
// the image of the factor alone.
TEST_F(TextureParity, SheenRoughnessTextureSetsTheLobeAndItsAlbedoAsOnTheCpu) {
  const nlohmann::json sheen = {{"KHR_materials_sheen",
                                 {{"sheenColorFactor", {1.0, 0.8, 0.6}},
                                  {"sheenRoughnessFactor", 1.0},
                                  {"sheenRoughnessTexture", {{"index", 0}}}}}};
  const scene::Scene scene = darkQuadUnderWhiteSky(dir_, "sheen", {{255, 255, 255, 40}, {255, 255, 255, 140}}, sheen);
  expectSlotsRenderAsOnTheCpu(device_, scene, {&materials::MaterialTextures::sheenRoughnessTexture});
  // The channel: where A is 64 (RGB 255) the sheen is the untextured
  // material's of roughness 64/255, its knots read between rows within
  // 0.0022 of its own; R would give roughness 1.
  const scene::Scene uniform =
      darkQuadUnderWhiteSky(dir_, "uniform", {{255, 255, 255, 64}, {255, 255, 255, 64}}, sheen);
  scene::Scene own = uniform;
  own.materials[0].textures->sheenRoughnessTexture = {};
  own.materials[0].sheenRoughness = 64.0 / 255.0;
  scene::Scene roughest = own;
  roughest.materials[0].sheenRoughness = 1.0;
  expectMeanAsTheFactorsSay("sheen", uniform, own, roughest, 2e-3, 0.02);
}

// A renderer keeps its upload of the textures between renders; each render
// must still show its own scene's textures: the same image as a fresh
// renderer's for a scene whose textures are new chains, reordered, or read
// through another sampler, and the first image again for the first scene.
TEST_F(TextureParity, AKeptRendererShowsEachScenesOwnTextures) {
  scene::Scene first = scene::loadScene(facet::testing::writeTexturedScene(dir_, "quad", 8, 2.0, 9987));
  first.render.width = 32;
  first.render.height = 24;
  const scene::SceneGeometry geometry = scene::buildGeometry(first);

  scene::Scene newChain = first;
  std::vector<scene::TextureLevel> inverted(first.textures[0].levels.begin(), first.textures[0].levels.end());
  for (scene::TextureLevel& level : inverted)
    for (glm::vec4& texel : level.texels) texel = glm::vec4(glm::vec3(1.0f) - glm::vec3(texel), texel.a);
  newChain.textures[0].levels = scene::TextureChain(std::move(inverted));
  scene::Scene reordered = first;
  std::swap(reordered.textures[0], reordered.textures[1]);
  scene::Scene resampled = first;
  resampled.textures[0].sampler.magFilter = rules::f64::FACET_FILTER_NEAREST;
  resampled.textures[0].sampler.minFilter = rules::f64::FACET_FILTER_NEAREST;

  gpu_backend::GpuRenderer kept(device_);
  const Image firstImage = kept.render(first, geometry).image;
  for (const scene::Scene* other : {&newChain, &reordered, &resampled}) {
    const Image keptImage = kept.render(*other, geometry).image;
    gpu_backend::GpuRenderer fresh(device_);
    const Image freshImage = fresh.render(*other, geometry).image;
    EXPECT_EQ(keptImage.beauty, freshImage.beauty);
    EXPECT_NE(keptImage.beauty, firstImage.beauty) << "the change shows in the image";
  }
  EXPECT_EQ(kept.render(first, geometry).image.beauty, firstImage.beauty);
}

INSTANTIATE_TEST_SUITE_P(BothMethods, TextureParity,
                         ::testing::Values(TextureCase{scene::IntersectionMethod::Exact, false},
                                           TextureCase{scene::IntersectionMethod::Tessellated, false},
                                           TextureCase{scene::IntersectionMethod::Exact, true},
                                           TextureCase{scene::IntersectionMethod::Exact, false, true}),
                         [](const auto& info) {
                           return std::string(info.param.method == scene::IntersectionMethod::Exact ? "exact"
                                                                                                    : "tessellated") +
                                  (info.param.environment ? "_environment" : "") +
                                  (info.param.jsonCube ? "_json_cube" : "");
                         });

}  // namespace
}  // namespace facet
