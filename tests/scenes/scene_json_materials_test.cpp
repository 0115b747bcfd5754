// Material files: named by a scene or by --material, extending one another,
// their errors naming the file; the material library in scenes/examples;
// --set over a JSON scene and over a bare model; a material put on objects
// by name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/studio_environment.h"
#include "tests/support/temp_dir.h"

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;


class MaterialFiles : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    fs::copy_file(fs::path(FACET_EXAMPLES_DIR) / "superball.obj", dir_ / "ball.obj");
    fs::create_directories(dir_ / "lib");
  }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  const materials::Material& materialOf(const Scene& scene, std::size_t object) {
    return scene.materials.at(std::size_t(scene.objects.at(object).material));
  }
  Scene withMaterial(const std::string& material, const std::vector<JsonOverride>& overrides = {}) {
    return loadScene(write("scene.json", R"({"objects": [{"mesh": "ball.obj", "material": )" + material + "}]}"),
                     overrides);
  }
  std::string errorOf(const std::string& material, const std::vector<JsonOverride>& overrides = {}) {
    try {
      withMaterial(material, overrides);
    } catch (const InputError& e) {
      return e.what();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(MaterialFiles, TheLibraryInTheExamplesLoadsAndWornGoldIsPolishedGoldRougher) {
  std::vector<Texture> textures;
  for (const char* file : {"polished_gold", "worn_gold", "brushed_aluminum", "red_plastic", "white_ceramic",
                           "glazed_ceramic", "car_paint", "velvet", "rubber"})
    EXPECT_NO_THROW(loadMaterialReference((fs::path(FACET_EXAMPLES_DIR) / "materials" / file).string() + ".json", textures)) << file;
  const materials::Material polished =
      loadMaterialReference((fs::path(FACET_EXAMPLES_DIR) / "materials" / "polished_gold.json").string(), textures);
  const materials::Material worn =
      loadMaterialReference((fs::path(FACET_EXAMPLES_DIR) / "materials" / "worn_gold.json").string(), textures);
  EXPECT_EQ(worn.f0, polished.f0);
  EXPECT_GT(worn.f0.r, 0.9);
  EXPECT_NEAR(polished.alpha, 0.2 * 0.2, 1e-12);
  EXPECT_NEAR(worn.alpha, 0.55 * 0.55, 1e-12);
  EXPECT_EQ(worn.name, "worn_gold");
  EXPECT_TRUE(textures.empty());
}

TEST_F(MaterialFiles, TheLibrarySceneNamesFilesFromItsMaterialsAndObjects) {
  const Scene scene = loadScene(fs::path(FACET_EXAMPLES_DIR) / "material_library.json");
  ASSERT_EQ(scene.objects.size(), 5u);
  EXPECT_NEAR(materialOf(scene, 0).alpha, 0.2 * 0.2, 1e-12);    // "gold": polished_gold.json
  EXPECT_NEAR(materialOf(scene, 1).alpha, 0.55 * 0.55, 1e-12);  // worn_gold.json, named by the object
  const materials::Material& blue = materialOf(scene, 4);       // red_plastic.json with its own diffuse
  EXPECT_EQ(blue.diffuse, glm::dvec3(0.04, 0.12, 0.5));
  EXPECT_NEAR(blue.alpha, 0.3 * 0.3, 1e-12);
}

TEST_F(MaterialFiles, AFileIsReadRelativeToWhatNamesItAndAnEntrysFieldsWin) {
  write("lib/base.json", R"({"preset": "copper", "roughness": 0.4, "diffuse": 0.1})");
  write("lib/derived.json", R"({"extends": "base.json", "diffuse": 0.2})");  // beside derived.json
  const Scene scene = withMaterial(R"({"extends": "lib/derived.json", "alpha": 0.09})");
  const materials::Material& m = materialOf(scene, 0);
  EXPECT_NEAR(m.alpha, 0.09, 1e-12);  // alpha replaces the file's roughness
  EXPECT_EQ(m.diffuse, glm::dvec3(0.2));
  EXPECT_GT(m.f0.r, m.f0.b);  // copper
}

TEST_F(MaterialFiles, TexturesInAFileAreRelativeToTheFile) {
  fs::create_directories(dir_ / "lib" / "maps");
  const std::vector<std::uint8_t> grey(4 * 2 * 3, 128);
  ASSERT_TRUE(stbi_write_png((dir_ / "lib" / "maps" / "albedo.png").c_str(), 4, 2, 3, grey.data(), 4 * 3));
  write("lib/painted.json",
        R"({"fresnel": "schlick", "f0": 0.04, "roughness": 0.5, "diffuse_texture": "maps/albedo.png"})");
  const Scene scene = withMaterial(R"("lib/painted.json")");
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_TRUE(materialOf(scene, 0).textures.has_value());
}

TEST_F(MaterialFiles, ErrorsNameTheFileThatBreaksTheRule) {
  EXPECT_THAT(errorOf(R"("lib/none.json")"), HasSubstr("objects[0].material: no such file:"));
  fs::create_directories(dir_ / "lib" / "folder.json");
  EXPECT_THAT(errorOf(R"("lib/folder.json")"), HasSubstr("objects[0].material: it is a folder, not a file:"));
  EXPECT_THAT(errorOf(R"({"extends": "lib/folder.json"})"),
              HasSubstr("objects[0].material.extends: it is a folder, not a file:"));
  write("lib/bad.json", R"({"preset": "gold", "roughness": 3})");
  EXPECT_THAT(errorOf(R"({"extends": "lib/bad.json"})"), HasSubstr("bad.json: roughness: must be in [0, 1], got 3"));
  write("lib/broken.json", R"({"preset": )");
  EXPECT_THAT(errorOf(R"("lib/broken.json")"), HasSubstr("broken.json: not valid JSON"));
  write("lib/list.json", "[1, 2]");
  EXPECT_THAT(errorOf(R"("lib/list.json")"), HasSubstr("list.json: the document: expected an object"));
  write("lib/a.json", R"({"extends": "b.json"})");
  write("lib/b.json", R"({"extends": "a.json", "roughness": 0.2})");
  EXPECT_THAT(errorOf(R"("lib/a.json")"),
              HasSubstr("b.json: extends: material files extend each other in a cycle: a.json -> b.json -> a.json"));
  write("lib/self.json", R"({"extends": "self.json"})");
  EXPECT_THAT(errorOf(R"("lib/self.json")"), HasSubstr("cycle: self.json -> self.json"));
  EXPECT_THAT(errorOf(R"({"extends": "gold"})"), HasSubstr("extends: a material file's name ends in .json"));
}

TEST_F(MaterialFiles, AChainOfExtendsIsBoundedBeforeTheStackIs) {
  constexpr int kDeepest = 64;
  const auto name = [](int i) { return "m" + std::to_string(i) + ".json"; };
  write("lib/" + name(kDeepest + 1), R"({"preset": "gold", "roughness": 0.3})");
  for (int i = kDeepest; i >= 1; --i) write("lib/" + name(i), R"({"extends": ")" + name(i + 1) + R"("})");
  // 64 files deep from the scene's entry: m1.json .. m64.json, the last extending m65.json.
  EXPECT_THAT(errorOf(R"("lib/m1.json")"),
              HasSubstr(name(kDeepest) + ": extends: material files extend each other more than 64 deep, from m1.json"));
  EXPECT_NO_THROW(withMaterial(R"("lib/m2.json")"));
  for (int i = kDeepest + 1; i < 4000; ++i)
    write("lib/" + name(i), R"({"extends": ")" + name(i + 1) + R"("})");
  write("lib/" + name(4000), R"({"preset": "gold", "roughness": 0.3})");
  EXPECT_THAT(errorOf(R"("lib/m1.json")"), HasSubstr("more than 64 deep"));
}

TEST_F(MaterialFiles, AMaterialNameMustNotLookLikeAFile) {
  write("scene.json", R"({"materials": {"gold.json": {"preset": "gold", "roughness": 0.2}},
                          "objects": [{"mesh": "ball.obj"}]})");
  EXPECT_THAT([&] { loadScene(dir_ / "scene.json"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("materials.gold.json: a material's name must not end")));
  write("scene.json", R"({"materials": {"g": "gold"}, "objects": [{"mesh": "ball.obj"}]})");
  EXPECT_THAT([&] { loadScene(dir_ / "scene.json"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("materials.g: expected an object of material fields")));
}

TEST_F(MaterialFiles, SetChangesTheDocumentBeforeItIsRead) {
  write("lib/base.json", R"({"preset": "gold", "roughness": 0.4})");
  const Scene scene =
      withMaterial(R"("lib/base.json")", {parseJsonOverride("objects[0].material.roughness=0.1"),
                                          parseJsonOverride("render.spp=4"), parseJsonOverride("camera.fov=30")});
  EXPECT_NEAR(materialOf(scene, 0).alpha, 0.01, 1e-12);  // reaches into the file the object names
  EXPECT_EQ(scene.render.samplesPerPixel, 4);
  EXPECT_EQ(scene.camera.verticalFovDegrees, 30);
  const Scene silver = withMaterial(R"("gold")", {parseJsonOverride("objects[0].material=silver")});
  EXPECT_GT(materialOf(silver, 0).f0.b, 0.85);  // silver's F(0), not gold's blue 0.29
}

TEST_F(MaterialFiles, AnOverrideThatBreaksARuleIsNamedWithTheField) {
  EXPECT_THAT(errorOf(R"("gold")", {parseJsonOverride("render.spp=15")}),
              HasSubstr("scene.json: render.spp (--set render.spp=15): samples per pixel must be a square number"));
  EXPECT_THAT(errorOf(R"({"preset": "gold", "roughness": 0.2})", {parseJsonOverride("objects[0].material.alpha=0.3")}),
              HasSubstr("(--set objects[0].material.alpha=0.3): give alpha or roughness, not both"));
  EXPECT_THAT(errorOf(R"("gold")", {parseJsonOverride("render.colour=1")}),
              HasSubstr("render.colour (--set render.colour=1): unknown field"));
  // An error elsewhere in the file is not blamed on the override.
  EXPECT_THAT(errorOf(R"("gold", "colour": 1)", {parseJsonOverride("render.spp=4")}),
              ::testing::AllOf(HasSubstr("objects[0].colour: unknown field"), ::testing::Not(HasSubstr("--set"))));
}

TEST_F(MaterialFiles, AModelTakesRenderCameraAndEnvironmentOverridesOnly) {
  const Scene plain = loadScene(dir_ / "ball.obj");
  const std::vector<JsonOverride> overrides = {parseJsonOverride("render.spp=9"), parseJsonOverride("camera.fov=25"),
                                               parseJsonOverride("environment.intensity=2")};
  const Scene scene = loadScene(dir_ / "ball.obj", overrides);
  EXPECT_EQ(scene.render.samplesPerPixel, 9);
  EXPECT_EQ(scene.camera.verticalFovDegrees, 25);
  EXPECT_EQ(scene.camera.eye, plain.camera.eye);  // the framed camera, narrower
  ASSERT_TRUE(scene.environment.has_value());
  EXPECT_EQ(scene.environment->intensity, 2);
  EXPECT_TRUE(isStudioEnvironment(*scene.environment));  // the map kept
  EXPECT_THAT([&] { loadScene(dir_ / "ball.obj", std::vector{parseJsonOverride("objects[0].material=gold")}); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  HasSubstr("a .obj model takes --set for render, camera and environment fields only")));
  EXPECT_THAT([&] { loadScene(dir_ / "ball.obj", std::vector{parseJsonOverride("camera.fov=200")}); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("--set: camera.fov: must be in [0.001, 179], is 200")));
  const Scene gltf =
      loadScene(fs::path(FACET_EXAMPLES_DIR) / "gold_cube.gltf", std::vector{parseJsonOverride("environment.color=[0.5, 0.5, 0.5]")});
  ASSERT_TRUE(gltf.environment.has_value());  // a model with lights gains the environment it is given
}

TEST_F(MaterialFiles, AMaterialGoesOnTheObjectsOfItsNameOrOnEvery) {
  write("scene.json", R"({"objects": [{"name": "cup", "mesh": "ball.obj"}, {"name": "lid", "mesh": "ball.obj"},
                                      {"name": "cup", "mesh": "ball.obj"}]})");
  Scene scene = loadScene(dir_ / "scene.json");
  materials::Material gold = loadMaterialReference("gold", scene.textures);
  EXPECT_NEAR(gold.alpha, defaultMaterial().alpha, 1e-12);  // a preset at the default roughness
  assignMaterial(scene, "cup", gold);
  EXPECT_GT(materialOf(scene, 0).f0.r, 0.9);
  EXPECT_EQ(materialOf(scene, 1).f0, glm::dvec3(0.04));
  EXPECT_EQ(scene.objects[0].material, scene.objects[2].material);
  EXPECT_THAT(
      [&] { assignMaterial(scene, "saucer", gold); },
      ::testing::ThrowsMessage<std::invalid_argument>("no object is called 'saucer' (the objects: 'cup', 'lid')"));
  assignMaterial(scene, "", loadMaterialReference("silver", scene.textures));
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(materialOf(scene, i).name, "silver");
  EXPECT_THAT([&] { loadMaterialReference("golld", scene.textures); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("--material: preset: unknown preset 'golld'")));
}

}  // namespace
}  // namespace facet::scene
