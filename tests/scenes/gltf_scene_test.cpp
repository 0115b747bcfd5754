// glTF meshes: triangles, strips and fans become the same polygons, rendered
// as authored by default.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"

#include <glm/geometric.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A ribbon of two rows, bottom vertices even and top ones odd (z varies, so
// no two triangles are coplanar), and a fan around vertex 0.
const std::vector<glm::vec3> kRibbon = {{0, 0, 0},   {0, 1, 0.2}, {1, 0, 0.1}, {1, 1, 0.4},
                                        {2, 0, 0.3}, {2, 1, 0.1}, {3, 0, 0.0}, {3, 1, 0.3}};
const std::vector<glm::vec3> kFan = {{0, 0, 0.5},  {1, 0, 0},       {0.5, 0.9, 0.1}, {-0.5, 0.9, 0},
                                     {-1, 0, 0.2}, {-0.5, -0.9, 0}, {0.5, -0.9, 0.1}};

class GltfMeshes : public facet::testing::TempDirTest {
 protected:
  // A one-mesh glTF file with its buffer beside it; no indices when
  // `indices` is empty.
  fs::path write(const std::string& name, const std::vector<glm::vec3>& positions,
                 const std::vector<std::uint16_t>& indices, int mode) {
    std::vector<char> bytes(positions.size() * sizeof(glm::vec3) + indices.size() * sizeof(std::uint16_t));
    std::memcpy(bytes.data(), positions.data(), positions.size() * sizeof(glm::vec3));
    if (!indices.empty())  // memcpy from an empty vector's null data is undefined, even for 0 bytes
      std::memcpy(bytes.data() + positions.size() * sizeof(glm::vec3), indices.data(),
                  indices.size() * sizeof(std::uint16_t));
    std::ofstream(dir_ / (name + ".bin"), std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    const std::size_t positionBytes = positions.size() * sizeof(glm::vec3);
    std::string accessors = R"({"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )" +
                            std::to_string(positions.size()) + "}";
    std::string views = R"({"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(positionBytes) + "}";
    std::string primitive = R"({"attributes": {"POSITION": 0}, "mode": )" + std::to_string(mode);
    if (!indices.empty()) {
      accessors += R"(, {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": )" +
                   std::to_string(indices.size()) + "}";
      views += R"(, {"buffer": 0, "byteOffset": )" + std::to_string(positionBytes) + R"(, "byteLength": )" +
               std::to_string(indices.size() * sizeof(std::uint16_t)) + "}";
      primitive += R"(, "indices": 1)";
    }
    std::ofstream(dir_ / (name + ".gltf"))
        << R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],)"
        << R"("meshes": [{"primitives": [)" << primitive << "}]}], \"accessors\": [" << accessors
        << "], \"bufferViews\": [" << views << R"(], "buffers": [{"uri": ")" << name << R"(.bin", "byteLength": )"
        << bytes.size() << "}]}";
    return dir_ / (name + ".gltf");
  }

};

using Triangle = std::array<glm::dvec3, 3>;

// Each face of the cage by the positions of its corners, starting at the
// smallest so that equal triangles of equal winding compare equal.
std::vector<Triangle> triangles(const Scene& scene) {
  const ControlCage& cage = scene.objects.at(0).cage;
  std::vector<Triangle> result;
  for (int f = 0; f < cage.faceCount(); ++f) {
    EXPECT_EQ(cage.faceVertexCounts[std::size_t(f)], 3);
    Triangle t;
    for (std::size_t c = 0; c < 3; ++c)
      t[c] = cage.positions[std::size_t(cage.faceVertexIndices[3 * std::size_t(f) + c])];
    auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::rotate(t.begin(), std::min_element(t.begin(), t.end(), less), t.end());
    result.push_back(t);
  }
  std::sort(result.begin(), result.end(), [](const Triangle& a, const Triangle& b) {
    return std::tie(a[0].x, a[0].y, a[0].z, a[1].x, a[1].y, a[1].z) <
           std::tie(b[0].x, b[0].y, b[0].z, b[1].x, b[1].y, b[1].z);
  });
  return result;
}

// `primitive` makes the triangles `list` makes, every one wound so that its
// normal's z has the sign of `facing`.
void expectTheTrianglesOf(const Scene& primitive, const Scene& list, std::size_t count, double facing) {
  const std::vector<Triangle> made = triangles(primitive);
  EXPECT_EQ(made, triangles(list));
  EXPECT_EQ(made.size(), count);
  for (const Triangle& t : made) EXPECT_GT(facing * glm::cross(t[1] - t[0], t[2] - t[0]).z, 0.0);
}

TEST_F(GltfMeshes, AStripIsTheTrianglesOfItsList) {
  // The list: the same ribbon, each triangle wound as the first (clockwise
  // seen from +z).
  expectTheTrianglesOf(loadScene(write("strip", kRibbon, {0, 1, 2, 3, 4, 5, 6, 7}, 5)),
                       loadScene(write("list", kRibbon, {0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4, 4, 5, 6, 5, 7, 6}, 4)), 6,
                       -1.0);
}

TEST_F(GltfMeshes, AFanIsTheTrianglesOfItsList) {
  expectTheTrianglesOf(loadScene(write("fan", kFan, {0, 1, 2, 3, 4, 5, 6, 1}, 6)),
                       loadScene(write("list", kFan, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 1}, 4)), 6,
                       1.0);
  // Without indices, the vertices in order.
  expectTheTrianglesOf(loadScene(write("unindexed", kFan, {}, 6)),
                       loadScene(write("list", kFan, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6}, 4)), 5, 1.0);
}

TEST_F(GltfMeshes, MeshesRenderAsAuthoredAndKeepTheirPositions) {
  const Scene scene = loadScene(write("fan", kFan, {0, 1, 2, 3, 4, 5, 6, 1}, 6));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].subdivision, Subdivision::None);
  const ControlCage& cage = scene.objects[0].cage;
  ASSERT_EQ(cage.vertexCount(), int(kFan.size()));
  for (std::size_t v = 0; v < kFan.size(); ++v) EXPECT_EQ(cage.positions[v], glm::dvec3(kFan[v]));
}

TEST_F(GltfMeshes, PrimitivesWithoutASurfaceAreErrors) {
  auto fails = [](const auto& message) { return ThrowsMessage<InputError>(message); };
  const fs::path lines = write("lines", kFan, {0, 1, 0, 2}, 1);
  EXPECT_THAT([&] { loadScene(lines); }, fails(AllOf(HasSubstr("lines.gltf"), HasSubstr("meshes[0].primitives[0]"),
                                                     HasSubstr("mode 1 has no surface"), HasSubstr("TRIANGLE_FAN 6"))));
  const fs::path shortStrip = write("short", kFan, {0, 1}, 5);
  EXPECT_THAT([&] { loadScene(shortStrip); },
              fails(AllOf(HasSubstr("short.gltf"), HasSubstr("a triangle strip needs at least 3 vertices, has 2"))));
  const fs::path ragged = write("ragged", kFan, {0, 1, 2, 3}, 4);
  EXPECT_THAT([&] { loadScene(ragged); }, fails(HasSubstr("not a multiple of 3")));
  const fs::path outside = write("outside", kFan, {0, 1, 9}, 6);
  EXPECT_THAT([&] { loadScene(outside); }, fails(HasSubstr("index 9 is out of range")));
}

// One triangle with a material, a camera and a spot light: a valid file whose
// fields the tests below break one at a time. Its buffer holds the triangle's
// positions, then the bytes 255, 1, 2, 0 for an index accessor.
nlohmann::json oneTriangle() {
  return nlohmann::json::parse(R"({
    "asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "color": [1, 1, 1], "intensity": 1, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.4}}]}},
    "scene": 0,
    "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 5]}, {"extensions": {"KHR_lights_punctual": {"light": 0}}}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0}}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5121, "count": 3, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 4}],
    "buffers": [{"uri": "triangle.bin", "byteLength": 40}]
  })");
}

class GltfFiles : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    const std::array<float, 9> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::array<std::uint8_t, 4> indices = {255, 1, 2, 0};
    std::ofstream bin(dir_ / "triangle.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(positions.data()), sizeof(positions));
    bin.write(reinterpret_cast<const char*>(indices.data()), sizeof(indices));
  }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }

  // The message `document` is rejected with, or "(no error)".
  std::string errorOf(const std::string& name, const std::string& text) {
    try {
      loadScene(write(name, text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  std::string errorOf(const nlohmann::json& document) { return errorOf("scene.gltf", document.dump()); }
};

std::string nested(int depth) { return std::string(std::size_t(depth), '[') + std::string(std::size_t(depth), ']'); }

// A .glb file of one JSON chunk and no binary chunk (glTF 2.0, 4.4).
std::string glb(std::string json) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  auto word = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  return "glTF" + word(2) + word(std::uint32_t(20 + json.size())) + word(std::uint32_t(json.size())) + "JSON" + json;
}

TEST_F(GltfFiles, TheTriangleLoads) {
  const Scene scene = loadScene(write("scene.gltf", oneTriangle().dump()));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.materials[std::size_t(scene.objects[0].material)].diffuse, glm::dvec3(0.5));
  EXPECT_NEAR(scene.camera.verticalFovDegrees, 0.6 * 180 / std::numbers::pi, 1e-9);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Spot);
  EXPECT_EQ(scene.lights[0].direction, glm::dvec3(0, 0, -1));
}

TEST_F(GltfFiles, NestingDeeperThanTheLimitIsRejectedBeforeParsing) {
  const std::string rule = "JSON nesting: arrays and objects nest deeper than 512 levels";
  // tinygltf copies "extras" into its own tree by recursion.
  const std::string deep = R"({"asset": {"version": "2.0"}, "extras": )" + nested(20000) + "}";
  EXPECT_THAT(errorOf("deep.gltf", deep), AllOf(HasSubstr("deep.gltf"), HasSubstr(rule)));
  EXPECT_THAT(errorOf("deep.glb", glb(deep)), AllOf(HasSubstr("deep.glb"), HasSubstr(rule)));
  EXPECT_THAT(errorOf("deep.gltf", nested(20000)), HasSubstr(rule));
  EXPECT_THAT(errorOf("deep.gltf", "{\"a\":" + nested(512) + "}"), HasSubstr(rule));
  // At the limit, and with brackets inside strings, which do not nest.
  nlohmann::json document = oneTriangle();
  document["extras"] = nlohmann::json::parse(nested(511));
  document["meshes"][0]["name"] = std::string(20000, '[');
  EXPECT_EQ(errorOf(document), "(no error)");
  EXPECT_EQ(errorOf("scene.glb", glb(document.dump())), "(no error)");
}

TEST_F(GltfFiles, LightsAreHeldToTheRulesOfJsonScenes) {
  nlohmann::json negative = oneTriangle();
  negative["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1, -0.5, 1};
  EXPECT_THAT(errorOf(negative), HasSubstr("scene.gltf: extensions.KHR_lights_punctual.lights[0].color: must not be "
                                           "negative"));
  for (auto [inner, outer] : {std::pair{0.5, 0.4}, std::pair{0.4, 0.4}, std::pair{-0.1, 0.4}, std::pair{0.2, 1.6}}) {
    nlohmann::json cones = oneTriangle();
    cones["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"] = {{"innerConeAngle", inner},
                                                                      {"outerConeAngle", outer}};
    EXPECT_THAT(errorOf(cones), HasSubstr("lights[0].spot: must have 0 <= innerConeAngle < outerConeAngle <= pi/2"));
  }
  // A singular matrix maps the light's -z to zero: it has no direction.
  nlohmann::json flat = oneTriangle();
  flat["nodes"][2]["scale"] = {1, 1, 0};
  EXPECT_THAT(errorOf(flat), HasSubstr("nodes[2]: the node's matrix is singular, so light 0 has no direction"));
}

TEST_F(GltfFiles, MaterialFactorsMustLieInZeroToOne) {
  nlohmann::json bright = oneTriangle();
  bright["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1.2, 0.5, 0.5, 1};
  EXPECT_THAT(errorOf(bright), HasSubstr("materials[0].pbrMetallicRoughness.baseColorFactor: every component must be "
                                         "in [0, 1], is 1.2"));
  nlohmann::json metal = oneTriangle();
  metal["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 2;
  EXPECT_THAT(errorOf(metal), HasSubstr("pbrMetallicRoughness.metallicFactor: must be in [0, 1], is 2"));
}

TEST_F(GltfFiles, CamerasAreHeldToTheRulesOfJsonScenes) {
  for (double yfov : {0.0, -0.5, 3.13}) {
    nlohmann::json camera = oneTriangle();
    camera["cameras"][0]["perspective"]["yfov"] = yfov;
    EXPECT_THAT(errorOf(camera), HasSubstr("cameras[0].perspective.yfov: in degrees, must be in [0.001, 179], is "));
  }
  nlohmann::json zero = oneTriangle();
  zero["nodes"][1]["matrix"] = std::vector<double>(16, 0.0);
  EXPECT_THAT(errorOf(zero), AllOf(HasSubstr("nodes[1]: the node's matrix is singular or not finite, so camera 0 "
                                             "has no view direction and up vector"),
                                   ::testing::Not(HasSubstr("--eye"))));
}

TEST_F(GltfFiles, AccessorsOfTheWrongFormatAreRejected) {
  nlohmann::json bytes = oneTriangle();
  bytes["accessors"][0]["componentType"] = 5120;
  EXPECT_THAT(errorOf(bytes), HasSubstr("meshes[0].primitives[0].POSITION: accessors[0] must be FLOAT VEC3, is "
                                        "componentType 5120 with 3 components"));
  // Signed indices could be negative: glTF allows only unsigned ones.
  nlohmann::json signedIndices = oneTriangle();
  signedIndices["meshes"][0]["primitives"][0]["indices"] = 1;
  signedIndices["accessors"][1]["componentType"] = 5120;
  EXPECT_THAT(errorOf(signedIndices), HasSubstr("accessors[1] must be SCALAR of UNSIGNED_BYTE"));
  signedIndices["accessors"][1]["componentType"] = 5121;
  EXPECT_THAT(errorOf(signedIndices), HasSubstr("meshes[0].primitives[0]: index 255 is out of range"));
}

TEST_F(GltfFiles, AnAccessorWhoseEndWrapsAroundIsRejected) {
  // 12-byte elements: (count - 1) * 12 is 3 * 2^64, which wraps to 0.
  nlohmann::json huge = oneTriangle();
  huge["accessors"][0]["count"] = (std::uint64_t(1) << 62) + 1;
  EXPECT_THAT(errorOf(huge), HasSubstr("POSITION: accessors[0] (count 4611686018427387905, byteOffset 0, stride 12) "
                                       "reads past the end of its buffer"));
  nlohmann::json offset = oneTriangle();
  offset["accessors"][0]["byteOffset"] = std::numeric_limits<std::uint64_t>::max() - 3;
  EXPECT_THAT(errorOf(offset), HasSubstr("reads past the end of its buffer"));
}

TEST_F(GltfFiles, IndicesOutOfRangeAreNamed) {
  nlohmann::json material = oneTriangle();
  material["meshes"][0]["primitives"][0]["material"] = 3;
  EXPECT_THAT(errorOf(material), HasSubstr("meshes[0].primitives[0].material: material index 3 out of range (the "
                                           "file has 1 materials)"));
  nlohmann::json scene = oneTriangle();
  scene["scene"] = 4;
  EXPECT_THAT(errorOf(scene), HasSubstr("scene.gltf: scene: scene index 4 out of range (the file has 1 scenes)"));
}

TEST_F(GltfFiles, TheNodeHierarchyMustBeAForest) {
  nlohmann::json twice = oneTriangle();
  twice["scenes"][0]["nodes"] = {0, 1, 2, 0};
  EXPECT_THAT(errorOf(twice), HasSubstr("scenes[0].nodes: node 0 is listed twice"));
  nlohmann::json twoParents = oneTriangle();
  twoParents["nodes"][1]["children"] = {2};
  twoParents["nodes"][0]["children"] = {2};
  twoParents["scenes"][0]["nodes"] = {0, 1};
  EXPECT_THAT(errorOf(twoParents), HasSubstr("nodes[1].children: node 2 is a child of node 0 too"));
  nlohmann::json cycle = oneTriangle();
  cycle["nodes"][0]["children"] = {0};
  EXPECT_THAT(errorOf(cycle), HasSubstr("scenes[0].nodes: node 0 is a root and a child of node 0"));
  // Without scenes, the roots are the nodes without a parent: a child is not drawn twice.
  nlohmann::json noScenes = oneTriangle();
  noScenes.erase("scenes");
  noScenes.erase("scene");
  noScenes["nodes"][1]["children"] = {0};
  EXPECT_EQ(loadScene(write("noscenes.gltf", noScenes.dump())).objects.size(), 1u);
}

TEST(GltfNormals, AreKeptPerFaceCorner) {
  const Scene scene = loadScene(std::string(FACET_TEST_DATA_DIR) + "/smooth_gem.gltf");
  ASSERT_EQ(scene.objects.size(), 1u);
  const ControlCage& cage = scene.objects[0].cage;
  ASSERT_EQ(cage.faceVertexNormals.size(), cage.faceVertexIndices.size());
  // The file's normals are its unit-sphere positions.
  for (std::size_t i = 0; i < cage.faceVertexIndices.size(); ++i)
    EXPECT_LT(glm::length(cage.faceVertexNormals[i] -
                          glm::normalize(cage.positions[std::size_t(cage.faceVertexIndices[i])])),
              1e-6);
}

}  // namespace
}  // namespace facet::scene
