// glTF textures: PNG images decode (through tinygltf's own stb_image), and
// a material's texture slots, samplers and transforms arrive as the file says.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace facet::scene {
namespace {

using facet::testing::Rgba8;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
namespace t = rules::f64;

class GltfTextures : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    // sRGB 188 is linear 0.5029; 0 and 255 are exact.
    ASSERT_TRUE(facet::testing::writePng(dir_ / "base.png", 4, 4,
                                         facet::testing::checkerTexels(4, 2, {188, 0, 255, 255}, {0, 255, 0, 128})));
    ASSERT_TRUE(facet::testing::writePng(dir_ / "mr.png", 2, 2, std::vector<Rgba8>(4, Rgba8{0, 128, 255, 255})));
  }

  // Material 0 reads base.png as its base colour and mr.png as its
  // metallic-roughness; `material` and `extra` add to or replace the file's members.
  nlohmann::json parts(const nlohmann::json& material = nlohmann::json::object()) {
    nlohmann::json m = {
        {"pbrMetallicRoughness",
         {{"baseColorTexture",
           {{"index", 0},
            {"extensions",
             {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.5}, {"scale", {2, 3}}}}}}}},
          {"metallicRoughnessTexture", {{"index", 1}}},
          {"roughnessFactor", 0.5}}},
        {"normalTexture", {{"index", 1}, {"scale", 0.75}}}};
    m.update(material);
    return {{"materials", {m}},
            {"textures", {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}}},
            {"samplers", {{{"magFilter", 9728}, {"minFilter", 9986}, {"wrapS", 33071}, {"wrapT", 33648}}}},
            {"images", {{{"uri", "base.png"}}, {{"uri", "mr.png"}}}}};
  }
};

TEST_F(GltfTextures, PngImagesDecodeIntoTheMaterialsSlots) {
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "quad", parts()));
  ASSERT_TRUE(scene.materials.at(0).textures.has_value());
  const materials::MaterialTextures& m = *scene.materials[0].textures;
  EXPECT_DOUBLE_EQ(m.roughness, 0.5);
  EXPECT_DOUBLE_EQ(m.normalScale, 0.75);
  // Texture 1 serves as data twice (one texture) and never as colour.
  ASSERT_EQ(scene.textures.size(), 2u);
  EXPECT_EQ(m.metallicRoughnessTexture.texture, m.normalTexture.texture);
  EXPECT_EQ(m.occlusionTexture.texture, -1);
  EXPECT_EQ(m.emissiveTexture.texture, -1);
  const materials::TextureSlot& base = m.baseColorTexture;
  EXPECT_EQ(base.offset, glm::dvec2(0.5, 0.25));
  EXPECT_EQ(base.scale, glm::dvec2(2, 3));
  EXPECT_DOUBLE_EQ(base.rotation, 0.5);

  const Texture& colour = scene.textures.at(std::size_t(base.texture));
  ASSERT_EQ(colour.levels.size(), 3u);  // 4 x 4, 2 x 2, 1 x 1
  EXPECT_EQ(colour.levels[2].width, 1);
  const glm::vec4 even = colour.levels[0].texels[0], odd = colour.levels[0].texels[2];
  EXPECT_NEAR(even.r, 0.50289, 1e-4);  // sRGB decoded
  EXPECT_EQ(even.g, 0.0f);
  EXPECT_EQ(even.b, 1.0f);
  EXPECT_EQ(even.a, 1.0f);
  EXPECT_NEAR(odd.a, 128.0 / 255.0, 1e-6);  // alpha stays linear
  // Each coarser level averages the linear values.
  EXPECT_NEAR(colour.levels[2].texels[0].r, 0.5 * 0.50289, 1e-4);
  EXPECT_EQ(colour.sampler.magFilter, t::FACET_FILTER_NEAREST);
  EXPECT_EQ(colour.sampler.minFilter, t::FACET_FILTER_NEAREST);
  EXPECT_EQ(colour.sampler.mipMode, t::FACET_MIP_LINEAR);
  EXPECT_EQ(colour.sampler.wrapS, t::FACET_WRAP_CLAMP_TO_EDGE);
  EXPECT_EQ(colour.sampler.wrapT, t::FACET_WRAP_MIRRORED_REPEAT);

  const Texture& data = scene.textures.at(std::size_t(m.metallicRoughnessTexture.texture));
  EXPECT_NEAR(data.levels[0].texels[0].g, 128.0 / 255.0, 1e-6);  // not decoded
  EXPECT_EQ(data.sampler.mipMode, t::FACET_MIP_LINEAR);          // glTF viewers' default
  EXPECT_EQ(data.sampler.wrapS, t::FACET_WRAP_REPEAT);
}

TEST_F(GltfTextures, AMaterialWithoutTexturesHasNoSlots) {
  nlohmann::json p = parts();
  p["materials"][0] = {{"pbrMetallicRoughness", {{"roughnessFactor", 0.5}}}};
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "plain", p));
  EXPECT_FALSE(scene.materials.at(0).textures.has_value());
  EXPECT_TRUE(scene.textures.empty());
}

TEST_F(GltfTextures, AMissingImageFileIsNamed) {
  nlohmann::json p = parts();
  p["images"][0]["uri"] = "nowhere.png";
  const auto file = facet::testing::writeTexturedQuad(dir_, "missing", p);
  EXPECT_THAT(
      [&] { loadScene(file); },
      ThrowsMessage<InputError>(AllOf(HasSubstr("missing.gltf"), HasSubstr("images[0]"), HasSubstr("nowhere.png"))));
}

TEST_F(GltfTextures, ABadTextureIndexIsNamed) {
  const auto file = facet::testing::writeTexturedQuad(dir_, "index", parts({{"normalTexture", {{"index", 7}}}}));
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("materials[0].normalTexture.index"),
                                              HasSubstr("texture index 7 out of range (the file has 2 textures)"))));
}

TEST_F(GltfTextures, ANegativeTextureIndexIsNamedNotIgnored) {
  const auto file = facet::testing::writeTexturedQuad(dir_, "negative", parts({{"normalTexture", {{"index", -3}}}}));
  EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(AllOf(HasSubstr("materials[0].normalTexture.index"),
                                                                        HasSubstr("texture index -3 out of range"))));
}

TEST_F(GltfTextures, AnImageOfAnUnknownFormatIsRefused) {
  std::ofstream(dir_ / "base.png") << "GIF89a, not a PNG";
  const auto file = facet::testing::writeTexturedQuad(dir_, "format", parts());
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("format.gltf"), HasSubstr("image[0]"))));
}

TEST_F(GltfTextures, AnUnknownWrapModeIsNamed) {
  nlohmann::json p = parts();
  p["samplers"][0]["wrapS"] = 1234;
  const auto file = facet::testing::writeTexturedQuad(dir_, "wrap", p);
  EXPECT_THAT([&] { loadScene(file); },
              ThrowsMessage<InputError>(AllOf(HasSubstr("samplers[0].wrapS"), HasSubstr("unknown wrap mode 1234"))));
}

TEST_F(GltfTextures, ABadTransformIsNamed) {
  const auto file = facet::testing::writeTexturedQuad(
      dir_, "transform",
      parts({{"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {1}}}}}}}}}));
  EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(
                                            "materials[0].emissiveTexture.extensions.KHR_texture_transform.scale: "
                                            "must be an array of 2 numbers")));
}

}  // namespace
}  // namespace facet::scene
