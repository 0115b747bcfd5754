// glTF tangents (glTF 2.0, 3.7.2.1): a primitive's TANGENT is read where its
// material takes a tangent, turned with the node and its sign flipped by a
// mirror; without one, MikkTSpace's is generated from the normals and the
// normal map's coordinates; a material that takes none carries none.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/subdivision_surface.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <optional>
#include <string>

namespace facet::scene {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;

// A quad whose normal map (any image; none is read here) asks for a tangent.
const nlohmann::json kNormalMapped = {{"materials", {{{"normalTexture", {{"index", 0}}}}}},
                                      {"textures", {{{"source", 0}}}},
                                      {"images", {{{"uri", "flat.png"}}}}};

class GltfTangents : public facet::testing::TempDirTest {
 protected:
  Scene load(nlohmann::json parts, std::optional<std::array<float, 4>> tangent, bool mirrored = false) {
    facet::testing::writePng(dir_ / "flat.png", 1, 1, {{128, 128, 255, 255}});
    parts["nodes"] = {{{"mesh", 0}, {"scale", {mirrored ? -1.0 : 1.0, 1.0, 1.0}}}};
    return loadScene(
        facet::testing::writeTexturedQuad(dir_, "quad", facet::testing::withQuadNormals(parts, dir_, "quad", tangent)));
  }
};

void expectEveryTangent(const ControlCage& cage, glm::dvec4 expected) {
  ASSERT_EQ(cage.faceVertexTangents.size(), cage.faceVertexIndices.size());
  for (const glm::dvec4& t : cage.faceVertexTangents) {
    EXPECT_NEAR(glm::length(glm::dvec3(t) - glm::dvec3(expected)), 0.0, 1e-12);
    EXPECT_EQ(t.w, expected.w);
  }
}

TEST_F(GltfTangents, AWrittenTangentIsRead) {
  const Scene scene = load(kNormalMapped, std::array<float, 4>{0, 2, 0, -1});
  EXPECT_THAT(scene.warnings, IsEmpty());
  expectEveryTangent(scene.objects.at(0).cage, {0, 1, 0, -1});
  // The patches carry them to shading, corner by corner.
  const SubdivisionSurface surface =
      SubdivisionSurface::create(scene.objects[0].cage, {.subdivision = Subdivision::None});
  ASSERT_TRUE(surface.hasAuthoredTangents());
  for (const glm::dvec4& t : *surface.authoredTangents(0)) EXPECT_EQ(t, glm::dvec4(0, 1, 0, -1));
}

TEST_F(GltfTangents, AMirrorFlipsTheSign) {
  // The bitangent w (n x t) is the mirror's image of the file's: n and t
  // keep their directions here, so w turns over.
  expectEveryTangent(load(kNormalMapped, std::array<float, 4>{0, 1, 0, 1}, true).objects.at(0).cage, {0, 1, 0, -1});
}

TEST_F(GltfTangents, WithoutTangentsMikkTSpaceGeneratesThem) {
  // u runs along +x and v down the image: t = +x, and the bitangent n x t =
  // +y points up the image, so w = 1; mirrored, t = -x and w = -1.
  expectEveryTangent(load(kNormalMapped, std::nullopt).objects.at(0).cage, {1, 0, 0, 1});
  expectEveryTangent(load(kNormalMapped, std::nullopt, true).objects.at(0).cage, {-1, 0, 0, -1});
}

TEST_F(GltfTangents, AMaterialThatTakesNoTangentCarriesNone) {
  const nlohmann::json plain = {{"materials", {{{"pbrMetallicRoughness", {{"roughnessFactor", 0.5}}}}}}};
  EXPECT_THAT(load(plain, std::array<float, 4>{0, 1, 0, 1}).objects.at(0).cage.faceVertexTangents, IsEmpty());
  EXPECT_THAT(load(plain, std::nullopt).objects.at(0).cage.faceVertexTangents, IsEmpty());
}

TEST_F(GltfTangents, ATangentWithoutASignIsAnError) {
  try {
    load(kNormalMapped, std::array<float, 4>{1, 0, 0, 0});
    FAIL() << "a tangent with w 0 loaded";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("meshes[0].primitives[0].TANGENT"));
    EXPECT_THAT(e.what(), HasSubstr("it must be 1 or -1"));
  }
}

}  // namespace
}  // namespace facet::scene
