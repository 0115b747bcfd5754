// Scene::set through the public API alone: each PATH=VALUE changes the scene
// as the same change to its file would (the file's document edited by hand
// here, independently of --set's code), and a refused one names the field,
// gives the file's rule and leaves the scene as it was.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <facet/facet.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "api_scenes.h"

namespace {

using namespace facet::testing;
using nlohmann::json;

json baseDocument() {
  return {{"camera", {{"eye", {2.5, 2, 3}}, {"target", {0, 0, 0}}, {"fov", 40}}},
          {"materials", {{"warm", {{"preset", "copper"}, {"roughness", 0.5}}}}},
          {"objects",
           {{{"name", "left"}, {"mesh", kCube}, {"material", "warm"}, {"transform", {{"translate", {0.6, 0, 0}}}}},
            {{"name", "right"}, {"mesh", kCube}, {"transform", {{"translate", {-0.8, 0, -0.5}}, {"scale", 0.5}}}}}},
          {"lights", {{{"type", "directional"}, {"direction", {-1, -2, -1}}, {"color", {2, 2, 2}}}}},
          {"environment", {{"file", kCourtyard}, {"intensity", 0.5}}}};
}

facet::Scene sceneOf(const json& document, const std::string& name) {
  return facet::loadScene(writeScene(name, document.dump()).string());
}

struct Change {
  std::string path, value;
  std::function<void(json&)> onFile;  // the same change, written into the file
};

std::vector<Change> changes() {
  return {
      {"camera.fov", "25", [](json& d) { d["camera"]["fov"] = 25; }},
      {"materials.warm.roughness", "0.2", [](json& d) { d["materials"]["warm"]["roughness"] = 0.2; }},
      {"materials.warm", R"({"preset": "silver", "roughness": 0.3})",
       [](json& d) {
         d["materials"]["warm"] = {{"preset", "silver"}, {"roughness", 0.3}};
       }},
      {"objects[1].material", "warm", [](json& d) { d["objects"][1]["material"] = "warm"; }},
      {"objects[0].material", "gold", [](json& d) { d["objects"][0]["material"] = "gold"; }},
      {"objects[1].material", R"({"diffuse": [0.7, 0.1, 0.1], "f0": [0.04, 0.04, 0.04], "roughness": 0.5})",
       [](json& d) {
         d["objects"][1]["material"] = {{"diffuse", {0.7, 0.1, 0.1}}, {"f0", {0.04, 0.04, 0.04}}, {"roughness", 0.5}};
       }},
      {"objects[1].subdivision", "none", [](json& d) { d["objects"][1]["subdivision"] = "none"; }},
      {"lights[0].color", "[1, 0.2, 0.2]",
       [](json& d) {
         d["lights"][0]["color"] = {1, 0.2, 0.2};
       }},
      {"environment.rotation", "90", [](json& d) { d["environment"]["rotation"] = 90; }},
      {"environment.intensity", "2", [](json& d) { d["environment"]["intensity"] = 2; }},
  };
}

TEST(ApiSceneSet, EachChangeRendersAsTheFileThatSaysTheSame) {
  for (const Change& c : changes()) {
    SCOPED_TRACE(c.path + "=" + c.value);
    facet::Scene scene = sceneOf(baseDocument(), "base.json");
    scene.set(c.path, c.value);
    json changed = baseDocument();
    c.onFile(changed);
    expectSameImage(render(scene), render(sceneOf(changed, "changed.json")));
  }
}

// The loaded cage is moved by the new transform after the old one's
// inverse, so the picture matches the file's to rounding, not bit for bit.
TEST(ApiSceneSet, ATransformFieldPlacesTheObjectAsTheFileDoes) {
  facet::Scene scene = sceneOf(baseDocument(), "base.json");
  scene.set("objects[0].transform.rotate", "[0, 40, 0]");
  EXPECT_EQ(scene.transform(0).rotate.y, 40);
  EXPECT_EQ(scene.transform(0).translate.x, 0.6) << "the file's transform, changed";
  json changed = baseDocument();
  changed["objects"][0]["transform"]["rotate"] = {0, 40, 0};
  const std::vector<float> a = render(scene).aov("beauty").values;
  const std::vector<float> b = render(sceneOf(changed, "turned.json")).aov("beauty").values;
  ASSERT_EQ(a.size(), b.size());
  double largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, double(std::abs(a[i] - b[i])));
  EXPECT_LT(largest, 1e-3);
}

TEST(ApiSceneSet, NamesAndTheRenderBlockChangeAsInTheFile) {
  facet::Scene scene = sceneOf(baseDocument(), "base.json");
  scene.set("objects[0].name", "teapot");
  EXPECT_EQ(scene.objectName(0), "teapot");
  scene.set("render.bounces", "2");
  facet::RenderSettings settings = small();
  EXPECT_EQ(renderer().render(scene, settings).bounces, 2);
}

TEST(ApiSceneSet, ARefusedChangeNamesTheFieldAndLeavesTheSceneAsItWas) {
  facet::Scene scene = sceneOf(baseDocument(), "base.json");
  const facet::Image before = render(scene);
  const auto fileError = [](const std::string& name, const std::function<void(json&)>& change) {
    json d = baseDocument();
    change(d);
    const std::filesystem::path file = writeScene(name, d.dump());
    return fieldAndRule(errorOf([&] { facet::loadScene(file.string()); }), file.string());
  };
  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.set("camera.fov", "500"); }), "scene"),
            fileError("fov.json", [](json& d) { d["camera"]["fov"] = 500; }));
  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.set("materials.warm.roughness", "2"); }), "scene"),
            fileError("rough.json", [](json& d) { d["materials"]["warm"]["roughness"] = 2; }));
  EXPECT_EQ(fieldAndRule(errorOf([&] { scene.set("lights[0].type", "laser"); }), "scene"),
            fileError("laser.json", [](json& d) { d["lights"][0]["type"] = "laser"; }));
  const std::vector<std::pair<std::string, std::string>> refusals = {
      {"objects[0].mesh", "objects[0].mesh: an object's mesh is not changed in place"},
      {"objects[7].name", "objects[7]: no such object (the scene has 2)"},
      {"objects[0].material.roughness", "objects[0].material.roughness: give the whole material"},
      {"camera_keys", "camera_keys: set changes render, camera, lights, environment, materials.NAME and objects[N]"},
      {"objects[0].transform.matrix", "objects[0].transform: give either matrix or translate/rotate/scale, not both"},
  };
  for (const auto& refusal : refusals) {
    const std::string refused = errorOf([&] { scene.set(refusal.first, "[1, 0, 0]"); });
    EXPECT_EQ(refused.rfind("scene: " + refusal.second, 0), 0u) << refused;
  }
  EXPECT_EQ(scene.objectName(0), "left");
  expectSameImage(render(scene), before);
}

// A file `set` names is found beside the scene file, as the file would name
// it; a file a setter is handed, in the working folder, as any file a
// program opens (docs/api.md).
TEST(ApiSceneSet, SetFindsFilesBesideTheSceneAndASetterInTheWorkingFolder) {
  facet::Scene scene = sceneOf(baseDocument(), "beside.json");
  const std::filesystem::path material = writeScene("beside_material.json", R"({"preset": "gold", "roughness": 0.3})");
  struct WorkingFolder {
    std::filesystem::path kept = std::filesystem::current_path();
    ~WorkingFolder() { std::filesystem::current_path(kept); }
  } restored;
  std::filesystem::current_path(restored.kept.root_path());
  EXPECT_NO_THROW(scene.set("objects[1].material", "\"beside_material.json\""));
  EXPECT_EQ(scene.materialName(1), "beside_material");
  const std::string refused = errorOf([&] { scene.setMaterial(0, std::string("beside_material.json")); });
  EXPECT_NE(refused.find("beside_material.json"), std::string::npos) << refused;
  EXPECT_EQ(scene.materialName(0), "warm");
  std::filesystem::current_path(material.parent_path());
  EXPECT_NO_THROW(scene.setMaterial(0, std::string("beside_material.json")));
  EXPECT_EQ(scene.materialName(0), "beside_material");
}

}  // namespace
