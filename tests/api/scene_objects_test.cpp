// A Scene's objects through the public API alone: a transform places a cage
// as a scene file's objects[].transform does, and replaces the one before;
// objects are added, removed and reordered, each refusal naming the field;
// a scene file's JSON given as text is the scene its file is.
#include <gtest/gtest.h>

#include <facet/facet.h>

#include <string>

#include "api_scenes.h"

namespace {

using namespace facet::testing;

facet::Transform turnedAndMoved() {
  facet::Transform t;
  t.translate = {0.4, -0.2, 0};
  t.rotate = {10, 35, 0};
  t.scale = {0.6, 0.8, 0.6};
  return t;
}

const char* kTurnedAndMovedBlock = R"({"translate": [0.4, -0.2, 0], "rotate": [10, 35, 0], "scale": [0.6, 0.8, 0.6]})";

// The cube alone under a fixed camera, so that moving it shows in the picture.
std::string cubeScene(const std::string& transform) {
  return R"({"camera": {"eye": [2.5, 2, 3], "target": [0, 0, 0], "fov": 40},
             "objects": [{"name": "cube", "mesh": ")" +
         kCube + "\"" + (transform.empty() ? "" : R"(, "transform": )" + transform) + "}]}";
}

TEST(ApiSceneObjects, ATransformPlacesTheCageAsTheSceneFileDoes) {
  const facet::Image placedByFile = render(facet::loadScene(writeScene("t.json", cubeScene(kTurnedAndMovedBlock))));
  facet::Scene scene = facet::loadScene(writeScene("plain.json", cubeScene("")).string());
  const facet::Image still = render(scene);
  scene.setTransform(0, turnedAndMoved());
  expectSameImage(render(scene), placedByFile);
  EXPECT_EQ(scene.transform(0).rotate.y, 35);

  // A transform replaces the one before; the identity puts the cage back.
  scene.setTransform(0, turnedAndMoved());
  expectSameImage(render(scene), placedByFile);
  scene.setTransform(0, {});
  const facet::Image back = render(scene);
  const std::vector<float>& a = back.aov("beauty").values;
  const std::vector<float>& b = still.aov("beauty").values;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(a[i], b[i], 1e-5) << i;

  facet::SceneDescription description;
  description.camera = scene.camera();
  description.objects = {{"cube", facet::loadCage(kCube), 0, true, turnedAndMoved()}};
  expectSameImage(render(facet::buildScene(description)), placedByFile);
}

TEST(ApiSceneObjects, ABadTransformIsRefusedWithTheFilesRule) {
  facet::Scene scene = facet::loadScene(kCube);
  facet::Transform flat;
  flat.scale = {1, 0, 1};
  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.setTransform(0, flat); }), "scene"),
            "objects[0].transform.scale: must not be zero");
  EXPECT_EQ(scene.transform(0).scale.y, 1);
  EXPECT_NE(errorOf([&] { scene.setTransform(3, flat); }).find("objects[3]: no such object"), std::string::npos);
}

TEST(ApiSceneObjects, ObjectsAreAddedRemovedAndReordered) {
  facet::Scene scene = facet::loadScene(writeScene("one.json", cubeScene("")).string());
  const facet::Image one = render(scene);
  facet::Object second{"second", facet::loadCage(kCube), 0, true, {}};
  second.transform.translate = {-1.2, 0, -1};
  second.transform.scale = {0.5, 0.5, 0.5};
  EXPECT_EQ(scene.addObject(second), 1);
  EXPECT_EQ(scene.objectCount(), 2);
  EXPECT_EQ(scene.objectName(1), "second");
  const std::string twoCubes = R"({"camera": {"eye": [2.5, 2, 3], "target": [0, 0, 0], "fov": 40},
      "objects": [{"name": "cube", "mesh": ")" +
                               kCube + R"("},
                  {"name": "second", "mesh": ")" +
                               kCube + R"(", "transform": {"translate": [-1.2, 0, -1], "scale": 0.5}}]})";
  expectSameImage(render(scene), render(facet::loadScene(writeScene("two.json", twoCubes).string())));

  scene.setMaterial(1, std::string("gold"));
  scene.moveObject(1, 0);
  EXPECT_EQ(scene.objectName(0), "second");
  EXPECT_EQ(scene.materialName(0), "gold");
  EXPECT_EQ(scene.transform(0).translate.x, -1.2);
  scene.removeObject(0);
  EXPECT_EQ(scene.objectCount(), 1);
  expectSameImage(render(scene), one);

  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.removeObject(0); }), "scene"),
            "objects[0]: is the scene's last object, and a scene needs at least one");
  facet::Object unknownMaterial = second;
  unknownMaterial.material = int(scene.materialNames().size());
  const std::string refused = errorOf([&] { scene.addObject(unknownMaterial); });
  EXPECT_NE(refused.find("scene: objects[1].material: "), std::string::npos) << refused;
  EXPECT_EQ(scene.objectCount(), 1);
}

TEST(ApiSceneObjects, ASceneFilesJsonAsTextIsTheSceneItsFileIs) {
  const std::string json = R"({"materials": {"warm": {"preset": "copper", "roughness": 0.4}},
    "objects": [{"mesh": "cube.obj", "material": "warm", "transform": )" +
                           std::string(kTurnedAndMovedBlock) + "}]}";
  const facet::Scene fromText = facet::sceneFromJson(json, FACET_CAGE_DIR);
  EXPECT_EQ(fromText.materialName(0), "warm");
  std::string inFolder = json;
  inFolder.replace(inFolder.find("cube.obj"), 8, kCube);
  expectSameImage(render(fromText), render(facet::loadScene(writeScene("text.json", inFolder).string())));

  EXPECT_EQ(errorOf([&] {
              facet::sceneFromJson(R"({"objects": [{"mesh": "nowhere.obj"}]})", FACET_CAGE_DIR);
            }).rfind("scene: objects[0].mesh: no such file: ", 0),
            0u);
  EXPECT_EQ(errorOf([] { facet::sceneFromJson("{\"objects\": ["); }).rfind("scene: not valid JSON: ", 0), 0u);
}

TEST(ApiSceneObjects, AGltfLoadsInTheMaterialVariantNamed) {
  // A triangle in material "red", which its variant "blue" maps to "blue".
  const std::string file = std::string(FACET_TEST_DATA_DIR) + "/variant_triangle.gltf";
  EXPECT_EQ(facet::loadScene(file).materialName(0), "red");
  EXPECT_EQ(facet::loadScene(file, "blue").materialName(0), "blue");
  EXPECT_NE(errorOf([&] {
              facet::loadScene(file, "green");
            }).find("no material variant is named 'green' (the file's: 'blue')"),
            std::string::npos);
}

}  // namespace
