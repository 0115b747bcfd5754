// Changing a loaded Scene (api/scene_edit.cpp) through the public API alone:
// a changed scene renders as the scene file that says the same, a refused
// change gives the file's error and leaves the scene as it was, and a loaded
// scene states its warnings.
#include <gtest/gtest.h>

#include <facet/facet.h>

#include <filesystem>
#include <string>

#include "api_scenes.h"

namespace {

using namespace facet::testing;

facet::Material redDiffuse() {
  facet::Material red;
  red.diffuse = facet::Vec3{0.8, 0.05, 0.05};
  red.f0 = facet::Vec3{0.04, 0.04, 0.04};
  red.roughness = 0.6;
  return red;
}

TEST(ApiSceneEdit, ARedDiffuseMaterialTurnsTheObjectRed) {
  facet::Scene scene = facet::loadScene(kCube);
  const facet::Vec3 grey = meanCovered(render(scene));
  EXPECT_NEAR(grey.x / grey.y, 1.0, 0.05);  // grey plastic under the grey studio map
  scene.setMaterial(0, redDiffuse());
  const facet::Vec3 red = meanCovered(render(scene));
  EXPECT_GT(red.x, 2 * red.y);
  EXPECT_LT(red.y, grey.y);
}

TEST(ApiSceneEdit, AChangedSceneRendersAsTheSceneFileThatSaysTheSame) {
  const std::string common = R"("camera": {"eye": [2.5, 2, 3], "target": [0, 0.1, 0], "up": [0, 1, 0], "fov": 35},
    "lights": [{"type": "directional", "direction": [-1, -2, -1], "color": [2, 1.8, 1.6]},
               {"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "color": [5, 5, 5],
                "inner_cone": 10, "outer_cone": 20}],
    "environment": {"file": ")" +
                             kCourtyard + R"(", "intensity": 0.5, "rotation": 30})";
  facet::Scene edited = facet::loadScene(kCube);
  edited.setCamera({{2.5, 2, 3}, {0, 0.1, 0}, {0, 1, 0}, 35});
  facet::Light key, spot;
  key.direction = {-1, -2, -1};
  key.color = {2, 1.8, 1.6};
  spot.type = facet::LightType::Spot;
  spot.position = {0, 4, 0};
  spot.color = {5, 5, 5};
  spot.innerCone = 10;
  spot.outerCone = 20;
  edited.setLights({key, spot});
  facet::Environment environment;
  environment.file = kCourtyard;
  environment.intensity = 0.5;
  environment.rotation = 30;
  edited.setEnvironment(environment);

  // A material written inline, and a preset by name.
  edited.setMaterial(0, redDiffuse());
  const std::filesystem::path inlineFile =
      writeScene("inline.json",
                 "{" + common + R"(, "objects": [{"mesh": ")" + kCube +
                     R"(", "material": {"diffuse": [0.8, 0.05, 0.05], "f0": [0.04, 0.04, 0.04], "roughness": 0.6}}]})");
  expectSameImage(render(edited), render(facet::loadScene(inlineFile.string())));

  edited.setMaterial(0, std::string("gold"));
  EXPECT_EQ(edited.materialName(0), "gold");
  const std::filesystem::path presetFile =
      writeScene("preset.json", "{" + common + R"(, "objects": [{"mesh": ")" + kCube + R"(", "material": "gold"}]})");
  expectSameImage(render(edited), render(facet::loadScene(presetFile.string())));

  // Anisotropy under the scene file's names.
  facet::Material brushed;
  brushed.preset = "aluminum";
  brushed.roughness = 0.3;
  brushed.anisotropy = 0.6;
  brushed.anisotropyRotation = 0.5;
  edited.setMaterial(0, brushed);
  const std::filesystem::path brushedFile =
      writeScene("brushed.json", "{" + common + R"(, "objects": [{"mesh": ")" + kCube +
                                     R"(", "material": {"preset": "aluminum", "roughness": 0.3, "anisotropy": 0.6,
                                             "anisotropy_rotation": 0.5}}]})");
  expectSameImage(render(edited), render(facet::loadScene(brushedFile.string())));
}

TEST(ApiSceneEdit, AChangeIsRefusedWithTheSceneFilesRuleAndLeavesTheSceneAsItWas) {
  facet::Scene scene = facet::loadScene(kCube);
  const facet::Camera before = scene.camera();
  const std::string material = scene.materialName(0), map = scene.environment()->file;
  const auto fileError = [](const std::string& name, const std::string& json) {
    const std::filesystem::path file = writeScene(name, json);
    return fieldAndRule(errorOf([&] { facet::loadScene(file.string()); }), file.string());
  };
  const std::string mesh = R"("objects": [{"mesh": ")" + kCube + R"("}])";

  facet::Camera wide = before;
  wide.fov = 500;
  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.setCamera(wide); }), "scene"),
            fileError("fov.json", R"({"camera": {"fov": 500}, )" + mesh + "}"));
  EXPECT_EQ(scene.camera().fov, before.fov);

  facet::Light spot;
  spot.type = facet::LightType::Spot;
  spot.innerCone = 50;
  spot.outerCone = 20;
  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.setLights({spot}); }), "scene"),
            fileError("cone.json", R"({"lights": [{"type": "spot", "position": [0, 0, 0], "direction": [0, -1, 0],
                                      "inner_cone": 50, "outer_cone": 20}], )" +
                                       mesh + "}"));
  EXPECT_TRUE(scene.lights().empty());

  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.setMaterial(0, std::string("unobtainium")); }), "scene"),
            fileError("preset.json", R"({"objects": [{"mesh": ")" + kCube + R"(", "material": "unobtainium"}]})"));
  facet::Material rough;
  rough.roughness = 2;
  const std::string refused = errorOf([&] { scene.setMaterial(0, rough); });
  EXPECT_NE(refused.find("objects[0].material.roughness"), std::string::npos) << refused;
  facet::Material stretched;
  stretched.roughness = 0.3;
  stretched.anisotropy = 1.5;
  const std::string overStretched = errorOf([&] { scene.setMaterial(0, stretched); });
  EXPECT_NE(overStretched.find("objects[0].material.anisotropy: must be in [0, 1]"), std::string::npos)
      << overStretched;

  facet::Environment missing;
  missing.file = "no_such_map.exr";
  EXPECT_NE(errorOf([&] { scene.setEnvironment(missing); }).find("scene: environment.file: "), std::string::npos);
  ASSERT_TRUE(scene.environment().has_value());
  EXPECT_EQ(scene.environment()->file, map);
  EXPECT_FALSE(scene.environment()->samples.has_value());  // unsaid: chosen with the paths

  EXPECT_NE(errorOf([&] { scene.setMaterial(1, redDiffuse()); }).find("objects[1]: no such object"), std::string::npos);
  EXPECT_EQ(scene.materialName(0), material);
}

TEST(ApiSceneEdit, CopiesKeepWhatTheyHad) {
  const facet::Scene original = facet::loadScene(kCube);
  facet::Scene changed = original;
  changed.setCamera({{0, 0, 9}, {0, 0, 0}, {0, 1, 0}, 20});
  EXPECT_EQ(changed.camera().fov, 20);
  EXPECT_NE(original.camera().fov, 20);
}

TEST(ApiSceneEdit, ALoadedCageBuildsTheSceneItsFileLoadsAs) {
  const facet::Cage cube = facet::loadCage(kCube);
  EXPECT_EQ(cube.positions.size(), 8u);
  facet::SceneDescription description;
  description.objects = {{"cube", cube, 0, true}};
  expectSameImage(render(facet::buildScene(description)), render(facet::loadScene(kCube)));

  const std::string lost = errorOf([] { facet::loadCage(std::string(FACET_CAGE_DIR) + "/boundary_hole.obj"); });
  EXPECT_NE(lost.find("load the file with loadScene"), std::string::npos) << lost;
}

TEST(ApiSceneEdit, ALoadedSceneStatesItsWarnings) {
  const std::string gltf = std::string(FACET_TEST_DATA_DIR) + "/ignored_features.gltf";
  const std::vector<std::string> warnings = facet::loadScene(gltf).warnings();
  ASSERT_FALSE(warnings.empty());
  bool colours = false;
  for (const std::string& w : warnings) colours |= w.find("only COLOR_0 is read") != std::string::npos;
  EXPECT_TRUE(colours);
  EXPECT_TRUE(facet::loadScene(kCube).warnings().empty());
}

}  // namespace
