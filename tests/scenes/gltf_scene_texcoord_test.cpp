// glTF TEXCOORD_0 becomes the cage's face-varying channel, held to the
// rules of the other attributes.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// Two triangles sharing an edge, as four vertices, and their texture
// coordinates: vertex 1 twice (a seam through it) at one position.
class GltfTexcoords : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    const std::array<float, 15> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 0};
    const std::array<float, 10> texcoords = {0, 0, 0.5, 0, 0.5, 1, 0, 1, 0.75, 0};
    const std::array<std::uint8_t, 6> indices = {0, 1, 3, 4, 2, 3};
    std::ofstream bin(dir_ / "quad.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions.data()), sizeof(positions));
    bin.write(reinterpret_cast<const char*>(texcoords.data()), sizeof(texcoords));
    bin.write(reinterpret_cast<const char*>(indices.data()), sizeof(indices));
  }

  static nlohmann::json quad() {
    return nlohmann::json::parse(R"({
      "asset": {"version": "2.0"},
      "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}]}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3"},
                    {"bufferView": 1, "componentType": 5126, "count": 5, "type": "VEC2"},
                    {"bufferView": 2, "componentType": 5121, "count": 6, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteLength": 60}, {"buffer": 0, "byteOffset": 60, "byteLength": 40},
                      {"buffer": 0, "byteOffset": 100, "byteLength": 6}],
      "buffers": [{"uri": "quad.bin", "byteLength": 106}]
    })");
  }

  fs::path write(const nlohmann::json& document) {
    std::ofstream(dir_ / "quad.gltf") << document.dump();
    return dir_ / "quad.gltf";
  }

  std::string errorOf(const nlohmann::json& document) {
    try {
      loadScene(write(document));
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(GltfTexcoords, BecomeOneValuePerWeldedVertexAndCoordinate) {
  const Scene scene = loadScene(write(quad()));
  const ControlCage& cage = scene.objects.at(0).cage;
  ASSERT_EQ(cage.vertexCount(), 4);  // vertices 1 and 4 welded
  ASSERT_EQ(cage.faceVertexTexcoords.size(), 6u);
  // Vertex 3 is shared with one coordinate: one value; vertex 1 is not.
  ASSERT_EQ(cage.texcoords.size(), 5u);
  EXPECT_EQ(cage.faceVertexTexcoords[2], cage.faceVertexTexcoords[5]);
  EXPECT_NE(cage.faceVertexTexcoords[1], cage.faceVertexTexcoords[3]);
  EXPECT_EQ(cage.texcoords[std::size_t(cage.faceVertexTexcoords[3])], glm::dvec2(0.75, 0.0));
  EXPECT_EQ(cage.texcoords[std::size_t(cage.faceVertexTexcoords[4])], glm::dvec2(0.5, 1.0));
}

TEST_F(GltfTexcoords, NormalizedIntegersMapToTheUnitSquare) {
  // The index bytes 0, 1, 3, 4, 2, 3 read as three normalized VEC2s.
  nlohmann::json bytes = quad();
  bytes["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}});
  bytes["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 3;
  bytes["meshes"][0]["primitives"][0].erase("indices");
  bytes["accessors"][0]["count"] = 3;
  const ControlCage& cage = loadScene(write(bytes)).objects.at(0).cage;
  ASSERT_EQ(cage.texcoords.size(), 3u);
  EXPECT_EQ(cage.texcoords[1], glm::dvec2(3.0 / 255, 4.0 / 255));
}

TEST_F(GltfTexcoords, AreOnlyReadWhenEveryPrimitiveHasThem) {
  nlohmann::json document = quad();
  document["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"indices", 2}});
  EXPECT_TRUE(loadScene(write(document)).objects.at(0).cage.faceVertexTexcoords.empty());
}

TEST_F(GltfTexcoords, BreakingTheirRulesIsAnError) {
  nlohmann::json count = quad();
  count["accessors"][1]["count"] = 4;
  EXPECT_THAT(errorOf(count), HasSubstr("meshes[0].primitives[0]: TEXCOORD_0 and POSITION have different counts"));
  nlohmann::json type = quad();
  type["accessors"][1]["type"] = "VEC3";
  EXPECT_THAT(errorOf(type), HasSubstr("meshes[0].primitives[0].TEXCOORD_0: accessors[1] must be VEC2 of FLOAT, "
                                       "UNSIGNED_BYTE or UNSIGNED_SHORT"));
  nlohmann::json past = quad();
  past["accessors"][1]["byteOffset"] = 8;
  EXPECT_THAT(errorOf(past), HasSubstr("TEXCOORD_0: accessors[1] (count 5, byteOffset 8, stride 8) reads past the "
                                       "end of its buffer"));
  // A NaN in vertex 0's coordinates.
  std::ofstream(dir_ / "quad.bin", std::ios::binary | std::ios::in | std::ios::out).seekp(64).write("\xff\xff\xff\x7f", 4);
  EXPECT_THAT(errorOf(quad()), HasSubstr("meshes[0].primitives[0]: TEXCOORD_0 0 is not finite"));
}

}  // namespace
}  // namespace facet::scene
