// A core property of the wrong JSON type is refused, naming the property and
// the type glTF 2.0 asks for: tinygltf alone would read it as absent and
// render another file than the one written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

namespace facet::scene {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

const nlohmann::json kQuadMaterials = {{{"doubleSided", true}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}}};

// The textured quad's members with one property given another type.
struct Mistyped {
  std::string name;
  nlohmann::json parts;
  std::string rule;  // what the error says after the file's name
};

std::vector<Mistyped> mistypedProperties() {
  const nlohmann::json primitive = {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}};
  const auto meshWith = [&](const char* key, const nlohmann::json& value) {
    nlohmann::json p = primitive;
    p[key] = value;
    return nlohmann::json{{"meshes", {{{"primitives", {p}}}}}};
  };
  nlohmann::json badAttribute = primitive["attributes"];
  badAttribute["POSITION"] = "0";
  nlohmann::json redFactor = kQuadMaterials;
  redFactor[0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 1, "red", 1};
  nlohmann::json sidedWord = kQuadMaterials;
  sidedWord[0]["doubleSided"] = "yes";
  return {
      {"required", {{"extensionsRequired", "KHR_materials_ior"}}, "extensionsRequired: must be an array"},
      {"used", {{"extensionsUsed", {1}}}, "extensionsUsed[0]: must be a string (glTF 2.0), is 1"},
      {"scene", {{"scene", "main"}}, "scene: must be a whole number (glTF 2.0), is \"main\""},
      {"node_mesh", {{"nodes", {{{"mesh", "0"}}}}}, "nodes[0].mesh: must be a whole number (glTF 2.0), is \"0\""},
      {"children", {{"nodes", {{{"mesh", 0}, {"children", {{"first", 1}}}}}}}, "nodes[0].children: must be an array"},
      {"translation", {{"nodes", {{{"mesh", 0}, {"translation", {1, "up", 0}}}}}}, "nodes[0].translation[1]: must be a number"},
      {"material", meshWith("material", 0.5), "meshes[0].primitives[0].material: must be a whole number (glTF 2.0), is 0.5"},
      {"attribute", meshWith("attributes", badAttribute), "meshes[0].primitives[0].attributes.POSITION: must be a whole number"},
      {"factor", {{"materials", redFactor}}, "materials[0].pbrMetallicRoughness.baseColorFactor[2]: must be a number"},
      {"sided", {{"materials", sidedWord}}, "materials[0].doubleSided: must be true or false (glTF 2.0), is \"yes\""},
      {"long", {{"asset", {{"version", std::vector<int>(100, 2)}}}},
       "asset.version: must be a string (glTF 2.0), is [2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2,2..."},
  };
}

using GltfSchema = facet::testing::TempDirTest;

TEST_F(GltfSchema, TheQuadAsWrittenLoads) {
  EXPECT_EQ(loadScene(facet::testing::writeTexturedQuad(dir_, "quad", {{"materials", kQuadMaterials}})).objects.size(),
            1u);
}

TEST_F(GltfSchema, APropertyOfTheWrongTypeIsNamedWithTheTypeItMustHave) {
  for (const Mistyped& c : mistypedProperties()) {
    SCOPED_TRACE(c.name);
    nlohmann::json parts = {{"materials", kQuadMaterials}};
    parts.update(c.parts);
    const auto file = facet::testing::writeTexturedQuad(dir_, c.name, parts);
    EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(c.name + ".gltf: " + c.rule)));
  }
}

}  // namespace
}  // namespace facet::scene
