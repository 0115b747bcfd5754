// glTF COLOR_0 and TEXCOORD_1 become face-varying channels of the cage, and
// a texture slot carries the set it reads; wrong formats, counts and sets
// are errors naming the field.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/subdivision_surface.h"
#include "tests/support/channels_gltf.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace facet::scene {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::ThrowsMessage;

class GltfChannels : public facet::testing::TempDirTest {
 protected:
  Scene load(const nlohmann::json& attributes, const nlohmann::json& parts = nlohmann::json::object()) {
    return loadScene(facet::testing::writeChannelQuad(dir_, "quad", attributes, parts));
  }
  std::string errorOf(const nlohmann::json& attributes, const nlohmann::json& parts = nlohmann::json::object()) {
    try {
      load(attributes, parts);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(GltfChannels, ColoursAndASecondSetBecomeChannelsOfTheCage) {
  for (int colourAccessor : {3, 4, 6}) {  // VEC4 of FLOAT, normalized VEC4 of UNSIGNED_BYTE, VEC3 of FLOAT
    const Scene scene = load({{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 2}, {"COLOR_0", colourAccessor}});
    EXPECT_THAT(scene.warnings, IsEmpty());
    const ControlCage& cage = scene.objects.at(0).cage;
    ASSERT_EQ(cage.faceVertexColors.size(), cage.faceVertexIndices.size());
    ASSERT_EQ(cage.faceVertexTexcoords1.size(), cage.faceVertexIndices.size());
    // Each corner's colour is its vertex's; alpha is not read.
    const glm::dvec3 expected[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (std::size_t c = 0; c < cage.faceVertexIndices.size(); ++c) {
      const glm::dvec3& p = cage.positions[std::size_t(cage.faceVertexIndices[c])];
      const int vertex = p.y < 0 ? (p.x < 0 ? 0 : 1) : (p.x > 0 ? 2 : 3);
      EXPECT_EQ(cage.colors[std::size_t(cage.faceVertexColors[c])], expected[vertex]);
      // TEXCOORD_1 mirrors TEXCOORD_0's u.
      const glm::dvec2 uv0 = cage.texcoords[std::size_t(cage.faceVertexTexcoords[c])];
      const glm::dvec2 uv1 = cage.texcoords1[std::size_t(cage.faceVertexTexcoords1[c])];
      EXPECT_EQ(uv1, glm::dvec2(1.0 - uv0.x, uv0.y));
    }
    // The untextured material is shaded per hit so that the colour reaches its base colour.
    ASSERT_TRUE(scene.materials.at(0).textures.has_value());
    EXPECT_EQ(scene.materials[0].textures->baseColor, glm::dvec3(1.0));
    const SubdivisionSurface surface = SubdivisionSurface::create(cage, {.subdivision = Subdivision::None});
    EXPECT_TRUE(surface.hasChannel(Channel::Color));
    EXPECT_TRUE(surface.hasChannel(Channel::Texcoord1));
  }
  // Colours on only some primitives of an object are not read, with a warning.
  const nlohmann::json partly = {
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}, {"COLOR_0", 3}}}, {"indices", 5}, {"material", 0}},
           {{"attributes", {{"POSITION", 0}}}, {"indices", 5}, {"material", 0}}}}}}}};
  const Scene some = load(nlohmann::json::object(), partly);
  EXPECT_TRUE(some.objects.at(0).cage.colors.empty());
  EXPECT_THAT(some.warnings, ::testing::ElementsAre(HasSubstr(
                                 "meshes[0].primitives[0].attributes.COLOR_0: not every primitive of its material has "
                                 "COLOR_0, so the object's vertex colours are not read")));
  // Without COLOR_0 the untextured material stays untextured, and the cage carries no colours.
  const Scene plain = load({{"POSITION", 0}, {"TEXCOORD_0", 1}});
  EXPECT_FALSE(plain.materials.at(0).textures.has_value());
  EXPECT_TRUE(plain.objects.at(0).cage.colors.empty());
  EXPECT_TRUE(plain.objects.at(0).cage.faceVertexTexcoords1.empty());
}

TEST_F(GltfChannels, AColourOfAnotherFormatCountOrRangeIsAnErrorNamingTheAccessor) {
  nlohmann::json accessors = facet::testing::channelQuadAccessors();
  EXPECT_THAT(errorOf({{"POSITION", 0}, {"COLOR_0", 1}}),
              HasSubstr("quad.gltf: meshes[0].primitives[0].COLOR_0: accessors[1] must be VEC3 or VEC4 of FLOAT, or "
                        "of normalized UNSIGNED_BYTE or UNSIGNED_SHORT, is componentType 5126 with 2 components"));
  accessors[4]["normalized"] = false;
  EXPECT_THAT(errorOf({{"POSITION", 0}, {"COLOR_0", 4}}, {{"accessors", accessors}}),
              HasSubstr("meshes[0].primitives[0].COLOR_0: accessors[4] must be VEC3 or VEC4 of FLOAT, or of "
                        "normalized UNSIGNED_BYTE or UNSIGNED_SHORT, is componentType 5121 without normalized: true"));
  accessors = facet::testing::channelQuadAccessors();
  accessors[3]["count"] = 3;
  EXPECT_THAT(errorOf({{"POSITION", 0}, {"COLOR_0", 3}}, {{"accessors", accessors}}),
              HasSubstr("meshes[0].primitives[0]: COLOR_0 and POSITION have different counts"));
  // POSITION read as colours: -1 is no colour.
  EXPECT_THAT(errorOf({{"POSITION", 0}, {"COLOR_0", 0}}),
              HasSubstr("meshes[0].primitives[0]: COLOR_0 0 has a component outside [0, 1], -1"));
  EXPECT_THAT(errorOf({{"POSITION", 0}, {"TEXCOORD_1", 3}}),
              HasSubstr("meshes[0].primitives[0].TEXCOORD_1: accessors[3] must be VEC2"));
}

TEST_F(GltfChannels, ASlotCarriesTheSetItReads) {
  ASSERT_TRUE(facet::testing::writePng(dir_ / "marker.png", 4, 4,
                                       facet::testing::checkerTexels(4, 2, {200, 20, 20, 255}, {20, 20, 200, 255})));
  const nlohmann::json images = {{"images", {{{"uri", "marker.png"}}}}, {"textures", {{{"source", 0}}}}};
  const auto material = [&](const nlohmann::json& slot) {
    nlohmann::json parts = images;
    parts["materials"] = {{{"doubleSided", true}, {"pbrMetallicRoughness", {{"baseColorTexture", slot}}}}};
    return parts;
  };
  const nlohmann::json attributes = {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 2}};
  EXPECT_EQ(
      load(attributes, material({{"index", 0}, {"texCoord", 1}})).materials.at(0).textures->baseColorTexture.texCoord,
      1);
  EXPECT_EQ(load(attributes, material({{"index", 0}})).materials.at(0).textures->baseColorTexture.texCoord, 0);
  // KHR_texture_transform's texCoord overrides the slot's.
  const nlohmann::json onSet1 = {{"KHR_texture_transform", {{"texCoord", 1}}}};
  nlohmann::json transformed = material({{"index", 0}, {"extensions", onSet1}});
  transformed["extensionsUsed"] = {"KHR_lights_punctual", "KHR_texture_transform"};
  EXPECT_EQ(load(attributes, transformed).materials.at(0).textures->baseColorTexture.texCoord, 1);
  EXPECT_THAT(errorOf(attributes, material({{"index", 0}, {"texCoord", 2}})),
              HasSubstr("materials[0].pbrMetallicRoughness.baseColorTexture.texCoord: only TEXCOORD_0 and TEXCOORD_1 "
                        "are read, not TEXCOORD_2"));
}

// Vertex colours go to the material a primitive renders in: in a variant
// that maps it to another material, that one takes them.
TEST_F(GltfChannels, AVariantsMaterialTakesThePrimitivesColours) {
  const nlohmann::json attributes = {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"COLOR_0", 3}};
  nlohmann::json parts = nlohmann::json::parse(R"({
    "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_variants"],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional"}]},
                   "KHR_materials_variants": {"variants": [{"name": "plain"}]}},
    "materials": [{"doubleSided": true}, {"doubleSided": true}],
    "meshes": [{"primitives": [{"indices": 5, "material": 0,
        "extensions": {"KHR_materials_variants": {"mappings": [{"material": 1, "variants": [0]}]}}}]}]
  })");
  parts["meshes"][0]["primitives"][0]["attributes"] = attributes;
  const std::filesystem::path file = facet::testing::writeChannelQuad(dir_, "variant", attributes, parts);
  const Scene own = loadScene(file);
  EXPECT_EQ(own.objects.at(0).material, 0);
  EXPECT_TRUE(own.materials[0].textures.has_value());
  const Scene plain = loadScene(file, {}, "plain");
  EXPECT_EQ(plain.objects.at(0).material, 1);
  EXPECT_TRUE(plain.materials[1].textures.has_value());  // shaded per hit, so the colour reaches its base colour
  EXPECT_FALSE(plain.materials[0].textures.has_value());
  EXPECT_EQ(plain.objects[0].cage.faceVertexColors.size(), plain.objects[0].cage.faceVertexIndices.size());
}

}  // namespace
}  // namespace facet::scene
