// glTF's KHR_materials_transmission, KHR_materials_volume and
// KHR_materials_ior: what a file says arrives as a transmissive material,
// and what facet cannot render is refused naming the field.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace facet::scene {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class GltfTransmission : public facet::testing::TempDirTest {
 protected:
  // A quad of one material with `extensions` and metallicFactor `metallic`.
  std::filesystem::path quad(const std::string& name, const nlohmann::json& extensions, double metallic = 0.0) {
    nlohmann::json material = {{"pbrMetallicRoughness", {{"metallicFactor", metallic}, {"roughnessFactor", 0.1}}},
                               {"extensions", extensions}};
    return facet::testing::writeTexturedQuad(dir_, name, {{"materials", {material}}});
  }
};

TEST_F(GltfTransmission, AVolumeIsAClosedAbsorbingDielectric) {
  const Scene scene = loadScene(quad(
      "volume", {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}}},
                 {"KHR_materials_ior", {{"ior", 1.4}}},
                 {"KHR_materials_volume",
                  {{"thicknessFactor", 0.5}, {"attenuationDistance", 2.0}, {"attenuationColor", {0.5, 0.6, 0.7}}}}}));
  const materials::Material& m = scene.materials.at(0);
  EXPECT_EQ(m.transmission, 0.75);
  EXPECT_EQ(m.fresnel, rules::f64::F_DIELECTRIC);
  EXPECT_EQ(m.eta, glm::dvec3(1.4));
  EXPECT_FALSE(m.thinWalled);
  EXPECT_EQ(m.attenuationDistance, 2.0);
  EXPECT_EQ(m.attenuationColor, glm::dvec3(0.5, 0.6, 0.7));
}

TEST_F(GltfTransmission, WithoutAVolumeTheSurfaceIsThinWalled) {
  const Scene scene = loadScene(quad("thin", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}));
  const materials::Material& m = scene.materials.at(0);
  EXPECT_TRUE(materials::isTransmissive(m));
  EXPECT_TRUE(m.thinWalled);
  EXPECT_EQ(m.eta, glm::dvec3(1.5));  // glTF's default index
  EXPECT_TRUE(std::isinf(m.attenuationDistance));
}

// KHR_materials_transmission: the texture scales the factor, the base colour
// tints and the metallic mix keeps a metal's share opaque, each per hit, so
// the material keeps its glTF parameters even without a texture.
TEST_F(GltfTransmission, TheTextureTheBaseColourAndAMetallicMixAreReadPerHit) {
  ASSERT_TRUE(facet::testing::writePng(dir_ / "mask.png", 2, 2,
                                       facet::testing::checkerTexels(2, 2, {255, 0, 0, 255}, {0, 0, 0, 255})));
  nlohmann::json material = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.5, 0.9, 1.0}}, {"metallicFactor", 0.25}}},
      {"extensions",
       {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}, {"transmissionTexture", {{"index", 0}}}}}}}};
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(
      dir_, "textured",
      {{"materials", {material}}, {"textures", {{{"source", 0}}}}, {"images", {{{"uri", "mask.png"}}}}}));
  const materials::Material& m = scene.materials.at(0);
  EXPECT_EQ(m.transmission, 0.75);
  ASSERT_TRUE(m.textures.has_value());
  EXPECT_GE(m.textures->transmissionTexture.texture, 0);
  EXPECT_EQ(m.textures->baseColor, glm::dvec3(0.2, 0.5, 0.9));
  EXPECT_EQ(m.textures->metallic, 0.25);

  const Scene plain = loadScene(quad("untextured", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}}, 1.0));
  ASSERT_TRUE(plain.materials.at(0).textures.has_value());
  EXPECT_EQ(plain.materials.at(0).textures->metallic, 1.0);
  EXPECT_LT(plain.materials.at(0).textures->transmissionTexture.texture, 0);
}

TEST_F(GltfTransmission, AnIndexAloneSetsTheOpaqueDielectricsF0) {
  const Scene scene = loadScene(quad("ior", {{"KHR_materials_ior", {{"ior", 2.0}}}}));
  EXPECT_FALSE(materials::isTransmissive(scene.materials.at(0)));
  EXPECT_NEAR(scene.materials.at(0).f0.x, 1.0 / 9.0, 1e-15);
  const Scene plain = loadScene(quad("plain", nlohmann::json::object()));
  EXPECT_EQ(plain.materials.at(0).f0, glm::dvec3(0.04));  // untouched without the extension
}

TEST_F(GltfTransmission, WhatCannotBeRenderedIsNamed) {
  auto refused = [&](const std::string& name, const nlohmann::json& extensions, const std::string& field,
                     const std::string& rule, double metallic = 0.0) {
    const auto file = quad(name, extensions, metallic);
    EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(AllOf(HasSubstr(field), HasSubstr(rule)))) << name;
  };
  refused("texture",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}, {"transmissionTexture", {{"index", 9}}}}}},
          "materials[0].extensions.KHR_materials_transmission.transmissionTexture", "out of range");
  refused("factor", {{"KHR_materials_transmission", {{"transmissionFactor", 2}}}},
          "KHR_materials_transmission.transmissionFactor", "must be in [0, 1]");
  refused("index", {{"KHR_materials_ior", {{"ior", 0.5}}}}, "KHR_materials_ior.ior", "must be in [1, 1000], is 0.5");
  refused("huge_index", {{"KHR_materials_ior", {{"ior", 2e19}}}}, "KHR_materials_ior.ior",
          "must be in [1, 1000], is 2e+19");
  refused("distance",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
           {"KHR_materials_volume", {{"thicknessFactor", 1}, {"attenuationDistance", 0}}}},
          "KHR_materials_volume.attenuationDistance", "must be > 0");
  refused("colour",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
           {"KHR_materials_volume", {{"thicknessFactor", 1}, {"attenuationColor", {1, 2, 0}}}}},
          "KHR_materials_volume.attenuationColor", "in [0, 1]");
}

}  // namespace
}  // namespace facet::scene
