// glTF meshes: the triangles of a mesh instance's primitives welded into one
// control cage.
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include "scenes/gltf_internal.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {
namespace {

// The glTF 2.0 specification's formats of mesh attributes and indices (3.7.2.1).
constexpr ElementFormat kFloatVec3{
    3, {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_FLOAT}, "FLOAT VEC3"};
constexpr ElementFormat kTexcoord{
    2,
    {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
    "VEC2 of FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT",
    true};
constexpr ElementFormat kVertexIndex{1,
                                     {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                     "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT"};

// Which vertices of a primitive's list make its triangle `t`, in the glTF 2.0
// specification's order (3.7.2.1): a strip swaps the last two of every other
// triangle so that all keep one winding, a fan turns about the first vertex.
std::array<std::size_t, 3> triangleCorners(int mode, std::size_t t) {
  switch (mode) {
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      return {t, t + 1 + t % 2, t + 2 - t % 2};
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return {t + 1, t + 2, 0};
    default:
      return {3 * t, 3 * t + 1, 3 * t + 2};
  }
}

std::size_t triangleCount(int mode, std::size_t vertices, const GltfReader& reader, const std::string& where) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (vertices % 3 != 0) reader.fail(where, "triangle index count is not a multiple of 3");
    return vertices / 3;
  }
  if (mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
    reader.fail(where, "mode " + std::to_string(mode) +
                           " has no surface (expected TRIANGLES 4, TRIANGLE_STRIP 5 or TRIANGLE_FAN 6)");
  if (vertices < 3)
    reader.fail(where, std::string(mode == TINYGLTF_MODE_TRIANGLE_STRIP ? "a triangle strip" : "a triangle fan") +
                           " needs at least 3 vertices, has " + std::to_string(vertices));
  return vertices - 2;
}

}  // namespace

ControlCage toCage(const tinygltf::Mesh& mesh, const std::vector<std::size_t>& primitives, const glm::dmat4& world,
                   const GltfReader& reader, const std::string& where) {
  ControlCage cage;
  cage.source = where;
  std::map<std::tuple<double, double, double>, int> welded;
  std::map<std::tuple<int, double, double>, int> texcoordValues;
  const auto everyPrimitiveHas = [&](const char* attribute) {
    return std::all_of(primitives.begin(), primitives.end(),
                       [&](std::size_t p) { return mesh.primitives[p].attributes.count(attribute) != 0; });
  };
  const bool normals = everyPrimitiveHas("NORMAL");
  const bool texcoords = everyPrimitiveHas("TEXCOORD_0");
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  for (std::size_t p : primitives) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    const std::string at = where + ".primitives[" + std::to_string(p) + "]";
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) reader.fail(at, "has no POSITION attribute");
    const std::vector<double> xyz = reader.read(position->second, at + ".POSITION", kFloatVec3);
    std::vector<int> remap(xyz.size() / 3, -1);
    std::vector<glm::dvec3> vertexNormals;
    if (normals) {
      const std::vector<double> n = reader.read(primitive.attributes.at("NORMAL"), at + ".NORMAL", kFloatVec3);
      if (n.size() != xyz.size()) reader.fail(at, "NORMAL and POSITION have different counts");
      for (std::size_t v = 0; v < n.size() / 3; ++v) {
        const glm::dvec3 transformed = normalMatrix * glm::dvec3(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
        const double length = glm::length(transformed);
        if (!(length > 0.0) || !std::isfinite(length))
          reader.fail(at, "NORMAL " + std::to_string(v) + " is zero or not finite");
        vertexNormals.push_back(transformed / length);
      }
    }
    std::vector<double> uv;
    if (texcoords) {
      uv = reader.read(primitive.attributes.at("TEXCOORD_0"), at + ".TEXCOORD_0", kTexcoord);
      if (uv.size() / 2 != remap.size()) reader.fail(at, "TEXCOORD_0 and POSITION have different counts");
      for (std::size_t v = 0; v < uv.size(); ++v)
        if (!std::isfinite(uv[v])) reader.fail(at, "TEXCOORD_0 " + std::to_string(v / 2) + " is not finite");
    }
    std::vector<double> indices;
    if (primitive.indices >= 0) {
      indices = reader.read(primitive.indices, at + ".indices", kVertexIndex);
    } else {
      for (std::size_t v = 0; v < remap.size(); ++v) indices.push_back(double(v));
    }
    for (double index : indices)
      if (index >= double(remap.size())) reader.fail(at, "index " + formatNumber(index) + " is out of range");
    // Primitives of other materials often share the POSITION accessor: the
    // cage takes only the vertices the indices use, in the accessor's order.
    for (double index : indices) remap[std::size_t(index)] = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
      const glm::dvec3 p3 = glm::dvec3(world * glm::dvec4(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0));
      if (!std::isfinite(p3.x) || !std::isfinite(p3.y) || !std::isfinite(p3.z))
        reader.fail(at, "POSITION " + std::to_string(v) + " is not finite");
      if (remap[v] < 0) continue;
      auto [it, inserted] = welded.try_emplace({p3.x, p3.y, p3.z}, cage.vertexCount());
      if (inserted) cage.positions.push_back(p3);
      remap[v] = it->second;
    }
    const std::size_t triangles = triangleCount(primitive.mode, indices.size(), reader, at);
    for (std::size_t t = 0; t < triangles; ++t) {
      int corners[3];
      std::size_t vertices[3];
      const std::array<std::size_t, 3> slots = triangleCorners(primitive.mode, t);
      for (int c = 0; c < 3; ++c) {
        vertices[c] = std::size_t(indices[slots[std::size_t(c)]]);
        corners[c] = remap[vertices[c]];
      }
      // A triangle with two corners at one position (strips join through
      // such triangles) has no area and would only add spurious topology.
      if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) continue;
      cage.faceVertexCounts.push_back(3);
      cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), corners, corners + 3);
      if (normals)
        for (std::size_t vertex : vertices) cage.faceVertexNormals.push_back(vertexNormals[vertex]);
      for (int c = 0; texcoords && c < 3; ++c) {
        const double s = uv[2 * vertices[c]], t = uv[2 * vertices[c] + 1];
        auto [it, inserted] = texcoordValues.try_emplace({corners[c], s, t}, int(cage.texcoords.size()));
        if (inserted) cage.texcoords.push_back({s, t});
        cage.faceVertexTexcoords.push_back(it->second);
      }
    }
  }
  if (glm::determinant(glm::dmat3(world)) < 0) {
    for (std::size_t f = 0; f < cage.faceVertexIndices.size(); f += 3) {
      std::swap(cage.faceVertexIndices[f + 1], cage.faceVertexIndices[f + 2]);
      if (normals) std::swap(cage.faceVertexNormals[f + 1], cage.faceVertexNormals[f + 2]);
      if (texcoords) std::swap(cage.faceVertexTexcoords[f + 1], cage.faceVertexTexcoords[f + 2]);
    }
  }
  return cage;
}

}  // namespace facet::scene::detail
