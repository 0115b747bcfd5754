// glTF primitives keep their own materials: a mesh whose primitives use two
// materials becomes two objects, and renders in both colours.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "engine/cpu/reference_renderer.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

namespace facet::scene {
namespace {

class GltfPrimitiveMaterials : public facet::testing::TempDirTest {};

nlohmann::json colour(const char* name, double r, double g, double b) {
  return {{"name", name}, {"pbrMetallicRoughness", {{"baseColorFactor", {r, g, b, 1.0}}, {"metallicFactor", 0.0}}}};
}

// The quad of textured_gltf.h as a mesh of `primitives`, each a list of
// (first index, material): the lower right triangle's indices start at 0, the
// upper left one's at 3; material -1 is none.
nlohmann::json quadOf(const std::vector<std::pair<int, int>>& primitives) {
  nlohmann::json parts = {{"materials", {colour("red", 0.8, 0.05, 0.05), colour("green", 0.05, 0.8, 0.05)}},
                          {"accessors", facet::testing::texturedQuadAccessors()}};
  // Accessors 2 and 3: each triangle's three indices.
  parts["accessors"][2]["count"] = 3;
  parts["accessors"].push_back(parts["accessors"][2]);
  parts["accessors"][3]["byteOffset"] = 6;
  nlohmann::json list = nlohmann::json::array();
  for (auto [first, material] : primitives) {
    nlohmann::json p = {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", first == 0 ? 2 : 3}};
    if (material >= 0) p["material"] = material;
    list.push_back(p);
  }
  parts["meshes"] = {{{"name", "quad"}, {"primitives", list}}};
  return parts;
}

TEST_F(GltfPrimitiveMaterials, EachMaterialOfAMeshIsAnObjectOfItsOwn) {
  const Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "two", quadOf({{0, 0}, {3, 1}})));
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[0].name, "quad");
  EXPECT_EQ(scene.objects[1].name, "quad.1");
  EXPECT_EQ(scene.materials.at(std::size_t(scene.objects[0].material)).name, "red");
  EXPECT_EQ(scene.materials.at(std::size_t(scene.objects[1].material)).name, "green");
  for (const Object& object : scene.objects) {
    EXPECT_EQ(object.cage.faceCount(), 1);
    EXPECT_EQ(object.cage.vertexCount(), 3);
    EXPECT_EQ(object.cage.texcoords.size(), 3u);
  }
}

TEST_F(GltfPrimitiveMaterials, PrimitivesSharingAMaterialWeldIntoOneCage) {
  const Scene scene =
      loadScene(facet::testing::writeTexturedQuad(dir_, "shared", quadOf({{0, 1}, {3, -1}, {3, 1}, {0, -1}})));
  ASSERT_EQ(scene.objects.size(), 2u);  // green twice, then the default material twice
  EXPECT_EQ(scene.materials.at(std::size_t(scene.objects[0].material)).name, "green");
  EXPECT_EQ(scene.objects[1].material, int(scene.materials.size()) - 1);  // the default
  for (const Object& object : scene.objects) {
    EXPECT_EQ(object.cage.faceCount(), 2);
    EXPECT_EQ(object.cage.vertexCount(), 4);  // the diagonal's two corners welded
  }
}

TEST_F(GltfPrimitiveMaterials, ATwoMaterialMeshRendersInBothColours) {
  Scene scene = loadScene(facet::testing::writeTexturedQuad(dir_, "render", quadOf({{0, 0}, {3, 1}})));
  scene.render.width = scene.render.height = 32;
  scene.camera = {{0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 40.0};
  const Image image = cpu::renderReference(scene, buildGeometry(scene));
  // Facing the camera, +y up: the lower right triangle is red, the upper left one green.
  const glm::vec4 lowerRight = image.beauty[std::size_t(24 * 32 + 24)];
  const glm::vec4 upperLeft = image.beauty[std::size_t(8 * 32 + 8)];
  ASSERT_EQ(lowerRight.a, 1.0f);
  ASSERT_EQ(upperLeft.a, 1.0f);
  EXPECT_GT(lowerRight.r, 4.0f * lowerRight.g);
  EXPECT_GT(upperLeft.g, 4.0f * upperLeft.r);
}

// KHR_materials_variants: the quad's lower right triangle red, which the
// variant "all green" maps to green and "blue" to a third material; the
// upper left triangle green in every variant.
nlohmann::json quadWithVariants() {
  nlohmann::json parts = quadOf({{0, 0}, {3, 1}});
  parts["materials"].push_back(colour("blue", 0.05, 0.05, 0.8));
  parts["extensionsUsed"] = {"KHR_materials_variants"};
  parts["extensions"]["KHR_materials_variants"]["variants"] = {{{"name", "all green"}}, {{"name", "blue"}}};
  parts["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] = {
      {{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}};
  return parts;
}

std::vector<std::string> objectMaterials(const Scene& scene) {
  std::vector<std::string> names;
  for (const Object& object : scene.objects) names.push_back(scene.materials.at(std::size_t(object.material)).name);
  return names;
}

TEST_F(GltfPrimitiveMaterials, AVariantNamedAtLoadReplacesTheMaterialsItMaps) {
  const std::filesystem::path file = facet::testing::writeTexturedQuad(dir_, "variants", quadWithVariants());
  const Scene own = loadScene(file);
  EXPECT_EQ(objectMaterials(own), (std::vector<std::string>{"red", "green"}));
  EXPECT_TRUE(own.warnings.empty());  // the extension is read: without a name, each primitive's own material
  // Both triangles in one material weld into one object.
  EXPECT_EQ(objectMaterials(loadScene(file, {}, "all green")), std::vector<std::string>{"green"});
  EXPECT_EQ(objectMaterials(loadScene(file, {}, "blue")), (std::vector<std::string>{"blue", "green"}));
}

TEST_F(GltfPrimitiveMaterials, AVariantTheFileLacksOrAMalformedMappingIsNamed) {
  const auto errorOf = [&](const nlohmann::json& parts, const std::string& variant) -> std::string {
    try {
      loadScene(facet::testing::writeTexturedQuad(dir_, "variants", parts), {}, variant);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_THAT(errorOf(quadWithVariants(), "teal"),
              ::testing::EndsWith("extensions.KHR_materials_variants: no material variant is named 'teal' (the "
                                  "file's: 'all green', 'blue')"));
  EXPECT_THAT(errorOf(quadOf({{0, 0}}), "teal"), ::testing::HasSubstr("(the file declares none)"));
  nlohmann::json outOfRange = quadWithVariants();
  outOfRange["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][1]["variants"] = {2};
  EXPECT_THAT(errorOf(outOfRange, "blue"),
              ::testing::EndsWith("meshes[0].primitives[0].extensions.KHR_materials_variants.mappings[1].variants[0]: "
                                  "must be the index of one of the file's 2 variants"));
  const std::string mappingMaterial = "mappings[0].material: must be the index of one of the file's 3 materials";
  for (const nlohmann::json& material : {nlohmann::json(), nlohmann::json(-1), nlohmann::json(3)}) {
    nlohmann::json bad = quadWithVariants();
    nlohmann::json& mapping = bad["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][0];
    if (material.is_null())
      mapping.erase("material");
    else
      mapping["material"] = material;
    // Checked whichever variant is named, and with none.
    for (const char* variant : {"blue", ""})
      EXPECT_THAT(errorOf(bad, variant), ::testing::HasSubstr(mappingMaterial)) << material << " " << variant;
  }
  EXPECT_THAT(errorOf(quadWithVariants(), ""), ::testing::Eq("(no error)"));
}

}  // namespace
}  // namespace facet::scene
