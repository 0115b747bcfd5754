// What facet does not render as a glTF file says is never dropped silently:
// a required extension it lacks refuses the file, and everything else it
// ignores is a warning on the scene naming the field.
#include <gmock/gmock.h>

#include <algorithm>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

namespace facet::scene {
namespace {

using ::testing::AllOf;
using ::testing::Contains;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::ThrowsMessage;
using ::testing::UnorderedElementsAre;

class GltfCoverage : public facet::testing::TempDirTest {
 protected:
  // The textured quad with one double-sided material of `material`'s members
  // added, and `parts` added to the file's.
  Scene load(const std::string& name, const nlohmann::json& material, nlohmann::json parts = nlohmann::json::object()) {
    nlohmann::json m = {{"doubleSided", true}};
    m.update(material);
    parts["materials"] = nlohmann::json::array({m});
    return loadScene(facet::testing::writeTexturedQuad(dir_, name, parts));
  }
};

TEST_F(GltfCoverage, AFileOfWhatFacetReadsHasNoWarnings) {
  const Scene scene = load("plain", {{"extensions", {{"KHR_materials_ior", {{"ior", 1.4}}}}}},
                           {{"extensionsUsed", {"KHR_materials_ior"}}, {"extensionsRequired", {"KHR_materials_ior"}}});
  EXPECT_THAT(scene.warnings, IsEmpty());
}

TEST_F(GltfCoverage, ARequiredExtensionFacetLacksRefusesTheFile) {
  EXPECT_THAT(
      [&] {
        load("prism", {{"extensions", {{"KHR_materials_dispersion", {{"dispersion", 1.0}}}}}},
             {{"extensionsUsed", {"KHR_materials_dispersion"}}, {"extensionsRequired", {"KHR_materials_dispersion"}}});
      },
      ThrowsMessage<InputError>(
          AllOf(HasSubstr("prism.gltf: extensionsRequired: extension KHR_materials_dispersion is "
                          "not supported"),
                HasSubstr("facet implements KHR_lights_punctual, KHR_materials_anisotropy, KHR_materials_clearcoat, "
                          "KHR_materials_emissive_strength"))));
}

TEST_F(GltfCoverage, EachIgnoredExtensionIsOneWarning) {
  const nlohmann::json prism = {{"dispersion", 1.0}};
  const Scene scene = load("used", {{"extensions", {{"KHR_materials_dispersion", prism}}}},
                           {{"extensionsUsed", {"KHR_materials_dispersion", "EXT_made_up"}}});
  EXPECT_THAT(scene.warnings,
              ElementsAre(AllOf(HasSubstr("used.gltf: extensionsUsed: extension KHR_materials_dispersion is not read"),
                                HasSubstr("one index of refraction for every wavelength")),
                          HasSubstr("extensionsUsed: extension EXT_made_up is not read; facet renders the file as if "
                                    "it were absent")));
  // An extension the file uses without listing it is found where it is.
  const Scene unlisted =
      load("unlisted", {{"extensions", {{"KHR_materials_diffuse_transmission", nlohmann::json::object()}}}});
  EXPECT_THAT(unlisted.warnings,
              ElementsAre(HasSubstr("materials[0].extensions.KHR_materials_diffuse_transmission: extension "
                                    "KHR_materials_diffuse_transmission is not read")));
}

TEST_F(GltfCoverage, IgnoredCoreFeaturesAreWarnings) {
  nlohmann::json parts = {
      {"animations", {{{"channels", nlohmann::json::array()}, {"samplers", nlohmann::json::array()}}}}};
  parts["meshes"] = {
      {{"primitives",
        {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"COLOR_1", 0}}}, {"indices", 2}, {"material", 0}}}}}};
  const Scene ignored = load("ignored", nlohmann::json::object(), parts);
  EXPECT_THAT(ignored.warnings,
              ElementsAre(HasSubstr("ignored.gltf: meshes[0].primitives[0].attributes.COLOR_1: only COLOR_0 is read"),
                          HasSubstr("animations: animations are not read")));
}

// A primitive without NORMAL is shaded flat and its TANGENT is not read
// (glTF 2.0, 3.7.2.1): warned where a normal map or an anisotropic lobe
// would take a tangent, and not on a material that takes none.
TEST_F(GltfCoverage, UnreadTangentsAreWarnedOnlyWhereATangentIsUsed) {
  nlohmann::json parts;
  parts["meshes"] = {
      {{"primitives",
        {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TANGENT", 0}}}, {"indices", 2}, {"material", 0}}}}}};
  EXPECT_THAT(load("plain_tangents", nlohmann::json::object(), parts).warnings, IsEmpty());
  EXPECT_THAT(load("anisotropic_tangents",
                   {{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.5}}}}}}, parts)
                  .warnings,
              ElementsAre(HasSubstr("meshes[0]: TANGENT is not read: not every primitive of its material has NORMAL")));
  ASSERT_TRUE(
      facet::testing::writePng(dir_ / "flat.png", 2, 2, std::vector<facet::testing::Rgba8>(4, {128, 128, 255, 255})));
  parts["textures"] = {{{"source", 0}}};
  parts["images"] = {{{"uri", "flat.png"}}};
  EXPECT_THAT(load("mapped_tangents", {{"normalTexture", {{"index", 0}}}}, parts).warnings,
              ElementsAre(HasSubstr("meshes[0]: TANGENT is not read: not every primitive of its material has NORMAL")));
}

TEST_F(GltfCoverage, AlphaModesAreRead) {
  // MASK is read: no warning; the object carries the cutoff, the factor's
  // alpha and the base colour slot.
  ASSERT_TRUE(facet::testing::writePng(dir_ / "alpha.png", 2, 2, std::vector<facet::testing::Rgba8>(4, {9, 9, 9, 9})));
  const Scene mask =
      load("mask",
           {{"alphaMode", "MASK"},
            {"alphaCutoff", 0.25},
            {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.75}}, {"baseColorTexture", {{"index", 0}}}}}},
           {{"textures", {{{"source", 0}}}}, {"images", {{{"uri", "alpha.png"}}}}});
  EXPECT_THAT(mask.warnings, IsEmpty());
  ASSERT_EQ(mask.objects.size(), 1u);
  EXPECT_EQ(mask.objects[0].alphaCutoff, 0.25);
  EXPECT_EQ(mask.objects[0].alphaFactor, 0.75);
  EXPECT_EQ(mask.objects[0].alphaTexture.texture, 0);
  EXPECT_TRUE(hasCutout(mask.objects[0]));
  EXPECT_EQ(mask.objects[0].alphaMode, AlphaMode::Mask);
  EXPECT_EQ(load("default_cutoff", {{"alphaMode", "MASK"}}).objects[0].alphaCutoff, 0.5);
  // MASK at a cutoff of 0 keeps every hit: opaque.
  EXPECT_FALSE(hasCutout(load("zero_cutoff", {{"alphaMode", "MASK"}, {"alphaCutoff", 0.0}}).objects[0]));
  // BLEND is read, without a warning: rays pass with probability 1 - alpha.
  const Scene blend = load("blend", {{"alphaMode", "BLEND"}});
  EXPECT_THAT(blend.warnings, IsEmpty());
  EXPECT_EQ(blend.objects[0].alphaMode, AlphaMode::Blend);
  EXPECT_TRUE(hasCutout(blend.objects[0]));
  EXPECT_FALSE(hasCutout(load("opaque", {{"alphaCutoff", 0.9}}).objects[0]));
}

// Morph targets at the weights the file gives (glTF 2.0, 3.7.2.2): the
// quad's own POSITION accessor as its one target, so that weight w scales the
// quad by 1 + w; the node's weights win over the mesh's, and none is 0.
TEST_F(GltfCoverage, MorphTargetsMoveTheMeshByTheirWeights) {
  const auto mesh = [](const nlohmann::json& weights) {
    nlohmann::json m = {{"primitives",
                         {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                           {"indices", 2},
                           {"material", 0},
                           {"targets", {{{"POSITION", 0}}}}}}}};
    if (!weights.is_null()) m["weights"] = weights;
    return nlohmann::json::array({m});
  };
  const auto largestX = [](const Scene& scene) {
    double x = 0.0;
    for (const glm::dvec3& p : scene.objects.at(0).cage.positions) x = std::max(x, p.x);
    return x;
  };
  const Scene half = load("half", nlohmann::json::object(), {{"meshes", mesh({0.5})}});
  EXPECT_THAT(half.warnings, IsEmpty());
  EXPECT_DOUBLE_EQ(largestX(half), 1.5);
  EXPECT_DOUBLE_EQ(largestX(load("unweighted", nlohmann::json::object(), {{"meshes", mesh(nullptr)}})), 1.0);
  EXPECT_DOUBLE_EQ(largestX(load("node", nlohmann::json::object(),
                                 {{"meshes", mesh({0.5})}, {"nodes", {{{"mesh", 0}, {"weights", {1.0}}}}}})),
                   2.0);
  EXPECT_THAT(
      [&] {
        load("counts", nlohmann::json::object(), {{"meshes", mesh({0.5, 0.25})}});
      },
      ThrowsMessage<InputError>(
          HasSubstr("counts.gltf: meshes[0].weights: has 2 weights, but meshes[0].primitives[0] has 1 morph targets")));
}

TEST_F(GltfCoverage, AlphaCutoffAndModeAreChecked) {
  EXPECT_THAT(
      [&] {
        load("word", {{"alphaMode", "MASK"}, {"alphaCutoff", "half"}});
      },
      ThrowsMessage<InputError>(
          HasSubstr("word.gltf: materials[0].alphaCutoff: must be a number (glTF 2.0), is \"half\"")));
  EXPECT_THAT(
      [&] {
        load("negative", {{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}});
      },
      ThrowsMessage<InputError>(
          HasSubstr("negative.gltf: materials[0].alphaCutoff: must be a number of at least 0, is -0.5")));
  EXPECT_THAT(
      [&] {
        load("mode", {{"alphaMode", "CUTOUT"}});
      },
      ThrowsMessage<InputError>(
          HasSubstr("mode.gltf: materials[0].alphaMode: must be OPAQUE, MASK or BLEND, is \"CUTOUT\"")));
}

TEST_F(GltfCoverage, OneSidedMaterialsCullTheirBackFaces) {
  // doubleSided false, written or by default, is read: no warning.
  const Scene single = load("single", {{"doubleSided", false}});
  EXPECT_THAT(single.warnings, IsEmpty());
  ASSERT_EQ(single.objects.size(), 1u);
  EXPECT_TRUE(single.objects[0].oneSided);
  EXPECT_FALSE(load("double", nlohmann::json::object()).objects[0].oneSided);
  // glTF's default material is one-sided too.
  nlohmann::json parts;
  parts["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 2}}}}}};
  EXPECT_TRUE(load("default", nlohmann::json::object(), parts).objects[0].oneSided);
}

TEST_F(GltfCoverage, LightRangesAndOrthographicCamerasAreWarnings) {
  nlohmann::json parts = {
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"range", 10.0}}}}}}}},
      {"cameras",
       {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 9}}}}}},
      {"nodes",
       {{{"mesh", 0}},
        {{"camera", 0}, {"translation", {0, 0, 3}}},
        {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 0, 2}}}}},
      {"scenes", {{{"nodes", {0, 1, 2}}}}}};
  EXPECT_THAT(
      load("range", nlohmann::json::object(), parts).warnings,
      UnorderedElementsAre(HasSubstr("nodes[1].camera: only perspective cameras are read"),
                           HasSubstr("extensions.KHR_lights_punctual.lights[0].range: is not read; the light falls off "
                                     "as 1/d^2")));
}

TEST_F(GltfCoverage, SparseAccessorsSubstituteTheirValues) {
  // Vertex 3 (the index at byte 10 of the index view) takes vertex 0's position
  // (the first of the position view): the upper left triangle loses its area.
  nlohmann::json parts = {{"accessors", facet::testing::texturedQuadAccessors()}};
  parts["accessors"][0]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", 2}, {"byteOffset", 10}, {"componentType", 5123}}},
                                     {"values", {{"bufferView", 0}}}};
  const Scene scene = load("sparse", nlohmann::json::object(), parts);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].cage.faceCount(), 1);
  EXPECT_EQ(scene.objects[0].cage.vertexCount(), 3);
  EXPECT_THAT(load("dense", nlohmann::json::object()).objects.at(0).cage.faceCount(), 2);
  // Without a buffer view the values are zeros before the substitution:
  // TEXCOORD_0 (0, 0) but at vertex 3, which takes the first of the view's (0, 1).
  nlohmann::json zeros = {{"accessors", facet::testing::texturedQuadAccessors()}};
  zeros["accessors"][1].erase("bufferView");
  zeros["accessors"][1]["sparse"] = parts["accessors"][0]["sparse"];
  zeros["accessors"][1]["sparse"]["values"] = {{"bufferView", 1}};
  const ControlCage cage = load("zeros", nlohmann::json::object(), zeros).objects.at(0).cage;
  EXPECT_THAT(cage.texcoords,  // one per vertex
              UnorderedElementsAre(glm::dvec2(0.0), glm::dvec2(0.0), glm::dvec2(0.0), glm::dvec2(0.0, 1.0)));
  zeros["accessors"][1]["count"] = 1 << 30;
  EXPECT_THAT([&] { load("huge", nlohmann::json::object(), zeros); },
              ThrowsMessage<InputError>(HasSubstr("accessors[1] has no buffer view, and such an accessor may have")));
  // An index past the accessor's count (a float's bits read as an integer) is an error.
  parts["accessors"][0]["sparse"]["indices"] = {{"bufferView", 0}, {"byteOffset", 0}, {"componentType", 5125}};
  EXPECT_THAT([&] { load("bad", nlohmann::json::object(), parts); },
              ThrowsMessage<InputError>(HasSubstr("POSITION: accessors[0].sparse.indices: index ")));
}

TEST_F(GltfCoverage, AnOcclusionMapOnAThirdCoordinateSetIsDroppedWithAWarning) {
  ASSERT_TRUE(facet::testing::writePng(dir_ / "grey.png", 4, 4,
                                       facet::testing::checkerTexels(4, 2, {90, 90, 90, 255}, {200, 200, 200, 255})));
  const nlohmann::json images = {{"images", {{{"uri", "grey.png"}}}}, {"textures", {{{"source", 0}}}}};
  const Scene scene = load("occlusion", {{"occlusionTexture", {{"index", 0}, {"texCoord", 2}}}}, images);
  EXPECT_FALSE(scene.materials.at(0).textures.has_value());  // the material reads no texture
  EXPECT_THAT(scene.warnings,
              ElementsAre(HasSubstr("materials[0].occlusionTexture.texCoord: only TEXCOORD_0 and TEXCOORD_1 are "
                                    "read, so this slot on TEXCOORD_2 is dropped: the environment")));
  // KHR_texture_transform's texCoord overrides the slot's; the base colour still reads TEXCOORD_0.
  const nlohmann::json onSet2 = {{"KHR_texture_transform", {{"texCoord", 2}}}};
  const Scene both = load("both",
                          {{"occlusionTexture", {{"index", 0}, {"extensions", onSet2}}},
                           {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
                          images);
  ASSERT_TRUE(both.materials.at(0).textures.has_value());
  EXPECT_GE(both.materials[0].textures->baseColorTexture.texture, 0);
  EXPECT_EQ(both.materials[0].textures->occlusionTexture.texture, -1);
  EXPECT_EQ(both.warnings.size(), 1u);
  // Any other slot on TEXCOORD_2 would render wrong: the file is refused.
  EXPECT_THAT(
      [&] {
        load("base", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 2}}}}}}, images);
      },
      ThrowsMessage<InputError>(HasSubstr("materials[0].pbrMetallicRoughness.baseColorTexture.texCoord: only "
                                          "TEXCOORD_0 and TEXCOORD_1 are read, not TEXCOORD_2")));
}

TEST_F(GltfCoverage, AClosedMeshOfAOneSidedMaterialIsNoWarning) {
  // A bipyramid of one material, doubleSided false by default.
  EXPECT_THAT(loadScene(std::string(FACET_TEST_DATA_DIR) + "/faceted_gem.gltf").warnings, IsEmpty());
}

TEST_F(GltfCoverage, RepeatedWarningsAreOneLine) {
  nlohmann::json parts;
  parts["meshes"] = {{{"primitives",
                       {{{"attributes", {{"POSITION", 0}, {"COLOR_1", 0}}}, {"indices", 2}},
                        {{"attributes", {{"POSITION", 0}, {"COLOR_1", 0}}}, {"indices", 2}},
                        {{"attributes", {{"POSITION", 0}, {"COLOR_1", 0}}}, {"indices", 2}}}}}};
  EXPECT_THAT(load("colours", nlohmann::json::object(), parts).warnings,
              ElementsAre(HasSubstr("meshes[0].primitives[0].attributes.COLOR_1 (and 2 more): only COLOR_0 is read")));
}

TEST_F(GltfCoverage, TinygltfWarningsArePassedOn) {
  // tinygltf warns of an image it cannot open; no texture uses this one.
  const Scene scene = load("image", nlohmann::json::object(), {{"images", {{{"uri", "missing.png"}}}}});
  EXPECT_THAT(scene.warnings, Contains(AllOf(HasSubstr("image.gltf: tinygltf: "), HasSubstr("image[0]"))));
}

}  // namespace
}  // namespace facet::scene
