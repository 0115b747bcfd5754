// glTF meshes: triangles, strips and fans become the same polygons, rendered
// as authored by default.
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "tests/support/temp_dir.h"

#include <glm/geometric.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
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
