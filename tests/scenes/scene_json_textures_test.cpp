// JSON scene materials that name image files for c_diff, F(0) and
// roughness: what the loader decodes into the scene's textures and slots,
// and the errors for bad texture fields.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <stb_image_write.h>

#include <cstdint>
#include <fstream>
#include <vector>

#include "rules/rules.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
namespace m = rules::f64;
using ::testing::AllOf;
using ::testing::HasSubstr;

class JsonTextures : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    fs::copy_file(fs::path(FACET_TEST_DATA_DIR) / "uv_checker_cube.obj", dir_ / "cube.obj");
    fs::create_directories(dir_ / "maps");
    // 4 x 2 texels: an sRGB grey of 128 and a one-channel roughness of 51.
    const std::vector<std::uint8_t> grey(4 * 2 * 3, 128), roughness(4 * 2, 51);
    ASSERT_TRUE(stbi_write_png((dir_ / "maps" / "albedo.png").c_str(), 4, 2, 3, grey.data(), 4 * 3));
    ASSERT_TRUE(stbi_write_png((dir_ / "maps" / "rough.png").c_str(), 4, 2, 1, roughness.data(), 4));
    std::ofstream(dir_ / "maps" / "broken.png") << "not an image";
  }

  Scene load(const std::string& material) {
    std::ofstream(dir_ / "scene.json") << R"({"objects": [{"mesh": "cube.obj", "material": )" + material + "}]}";
    return loadScene(dir_ / "scene.json");
  }
  std::string errorOf(const std::string& material) {
    try {
      load(material);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(JsonTextures, ADiffuseTextureIsTheBaseColourOfADielectric) {
  const Scene scene = load(R"({"diffuse_texture": "maps/albedo.png", "roughness_texture": "maps/rough.png",
                               "f0": 0.04, "fresnel": "schlick"})");
  ASSERT_EQ(scene.textures.size(), 2u);
  const materials::Material& material = scene.materials.at(0);
  ASSERT_TRUE(material.textures);
  const materials::MaterialTextures& t = *material.textures;
  EXPECT_EQ(t.metallic, 0.0);
  EXPECT_EQ(t.baseColor, glm::dvec3(1.0));  // no diffuse factor: the texture as it is
  EXPECT_EQ(t.roughness, 1.0);
  EXPECT_EQ(t.baseColorTexture.texture, 0);
  EXPECT_EQ(t.metallicRoughnessTexture.texture, 1);
  const glm::vec4 albedo = scene.textures[0].levels[0].texels.at(0);
  EXPECT_NEAR(albedo.r, m::srgb_to_linear(128.0 / 255.0), 1e-6);  // sRGB-decoded
  EXPECT_EQ(albedo.a, 1.0f);
  EXPECT_EQ(scene.textures[0].levels[0].width, 4);
  // Roughness in G as the file holds it; metallic (B) 1 times the factor 0.
  EXPECT_EQ(scene.textures[1].levels[0].texels.at(0), glm::vec4(1.0f, 51.0f / 255.0f, 1.0f, 1.0f));
  EXPECT_EQ(scene.textures[0].sampler.wrapS, m::FACET_WRAP_REPEAT);
  EXPECT_EQ(scene.textures[0].sampler.mipMode, m::FACET_MIP_LINEAR);
}

TEST_F(JsonTextures, AnF0TextureIsTheBaseColourOfAMetalAndFactorsMultiply) {
  const Scene scene = load(R"({"fresnel": "schlick", "f0": [0.5, 0.5, 0.5], "roughness": 0.3,
                               "f0_texture": {"image": "maps/albedo.png", "wrap": "clamp", "filter": "nearest"},
                               "roughness_texture": "maps/rough.png"})");
  const materials::MaterialTextures& t = scene.materials.at(0).textures.value();
  EXPECT_EQ(t.metallic, 1.0);
  EXPECT_EQ(t.baseColor, glm::dvec3(0.5));
  EXPECT_NEAR(t.roughness, 0.3, 1e-12);
  const TextureSampler& s = scene.textures.at(0).sampler;
  EXPECT_EQ(s.wrapS, m::FACET_WRAP_CLAMP_TO_EDGE);
  EXPECT_EQ(s.wrapT, m::FACET_WRAP_CLAMP_TO_EDGE);
  EXPECT_EQ(s.magFilter, m::FACET_FILTER_NEAREST);
  EXPECT_EQ(s.mipMode, m::FACET_MIP_NEAREST);
}

TEST_F(JsonTextures, AMaterialWithoutTextureFieldsReadsNoTexture) {
  const Scene scene = load(R"({"diffuse": 0.5, "roughness": 0.5})");
  EXPECT_FALSE(scene.materials.at(0).textures);
  EXPECT_TRUE(scene.textures.empty());
}

TEST_F(JsonTextures, ErrorsNameTheFileTheFieldAndTheRule) {
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": "maps/missing.png"})"),
              AllOf(HasSubstr("scene.json"), HasSubstr("objects[0].material.diffuse_texture"),
                    HasSubstr("no such file"), HasSubstr("missing.png")));
  ASSERT_EQ(mkfifo((dir_ / "maps" / "pipe.png").c_str(), 0600), 0);
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": "maps/pipe.png"})"),
              AllOf(HasSubstr("objects[0].material.diffuse_texture"),
                    HasSubstr("it is a FIFO, socket or device, not a regular file"), HasSubstr("pipe.png")));
  fs::create_directories(dir_ / "maps" / "folder.png");
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": "maps/folder.png"})"),
              AllOf(HasSubstr("objects[0].material.diffuse_texture"), HasSubstr("it is a folder, not a file")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": {"image": "maps/broken.png"}})"),
              AllOf(HasSubstr("objects[0].material.diffuse_texture.image"), HasSubstr("cannot decode the image")));
  EXPECT_THAT(
      errorOf(R"({"roughness": 0.5, "diffuse_texture": {"image": "maps/albedo.png", "wrap": "tile"}})"),
      AllOf(HasSubstr("diffuse_texture.wrap"), HasSubstr("unknown value 'tile'"), HasSubstr("repeat, mirror, clamp")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": {"image": "maps/albedo.png", "filter": "cubic"}})"),
              AllOf(HasSubstr("diffuse_texture.filter"), HasSubstr("linear, nearest")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": {"file": "maps/albedo.png"}})"),
              AllOf(HasSubstr("diffuse_texture.file"), HasSubstr("unknown field")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "diffuse_texture": 3})"),
              AllOf(HasSubstr("diffuse_texture"), HasSubstr("expected an image file name or an object")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "fresnel": "dielectric", "ior": 1.5, "f0_texture": "maps/albedo.png"})"),
              AllOf(HasSubstr("objects[0].material.f0_texture"), HasSubstr("needs a fresnel that reads f0")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "f0": 0.9, "diffuse_texture": "maps/albedo.png"})"),
              AllOf(HasSubstr("diffuse_texture"), HasSubstr("needs f0 0.04")));
  EXPECT_THAT(
      errorOf(
          R"({"roughness": 0.5, "f0": 0.9, "diffuse_texture": "maps/albedo.png", "f0_texture": "maps/albedo.png"})"),
      AllOf(HasSubstr("diffuse_texture"), HasSubstr("cannot be combined with f0_texture")));
  EXPECT_THAT(errorOf(R"({"roughness": 0.5, "f0": 0.9, "diffuse": 0.5, "roughness_texture": "maps/rough.png"})"),
              AllOf(HasSubstr("roughness_texture"), HasSubstr("needs diffuse 0 or f0 0.04")));
}

}  // namespace
}  // namespace facet::scene
