// glTF meshes' tangents (glTF 2.0, 3.7.2.1): a primitive's TANGENT where it
// has one, else MikkTSpace's over the mesh's normals and the texture
// coordinates of its normal map, as the specification asks of a client.
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

#include "scenes/gltf_internal.h"
#include "scenes/mikktspace.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {
namespace {

constexpr ElementFormat kTangentFormat{
    4, {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_FLOAT}, "FLOAT VEC4"};

}  // namespace

bool usesTangents(const tinygltf::Model& model, int index) {
  if (index < 0 || std::size_t(index) >= model.materials.size()) return false;
  const tinygltf::Material& m = model.materials[std::size_t(index)];
  if (m.normalTexture.index >= 0 || m.extensions.count("KHR_materials_anisotropy") > 0) return true;
  const auto coat = m.extensions.find("KHR_materials_clearcoat");
  return coat != m.extensions.end() && coat->second.Has("clearcoatNormalTexture");
}

std::optional<int> tangentTexcoordSet(const tinygltf::Model& model, int index, const materials::Material& material) {
  if (!usesTangents(model, index)) return std::nullopt;
  if (material.textures) {
    // The sets the slots read, KHR_texture_transform's texCoord included.
    if (material.textures->normalTexture.texture >= 0) return material.textures->normalTexture.texCoord;
    if (material.textures->clearcoatNormalTexture.texture >= 0)
      return material.textures->clearcoatNormalTexture.texCoord;
  }
  return 0;
}

std::vector<glm::dvec4> primitiveTangents(const tinygltf::Primitive& primitive, std::size_t vertices,
                                          const glm::dmat4& world, const std::vector<double>& weights,
                                          const GltfReader& reader, const std::string& at) {
  const std::string where = at + ".TANGENT";
  const std::vector<double> values = reader.read(primitive.attributes.at("TANGENT"), where, kTangentFormat);
  if (values.size() != 4 * vertices) reader.fail(at, "TANGENT and POSITION have different counts");
  std::vector<double> xyz;
  for (std::size_t v = 0; v < vertices; ++v) xyz.insert(xyz.end(), &values[4 * v], &values[4 * v + 3]);
  // A morph target moves the tangent's direction (a VEC3 delta), never its sign.
  morph(xyz, primitive, "TANGENT", weights, reader, at);
  // Tangents turn with the surface (not as normals do); a mirror flips the
  // bitangent w (n x t) names, so w flips with it.
  const glm::dmat3 turn(world);
  const double mirror = glm::determinant(turn) < 0.0 ? -1.0 : 1.0;
  std::vector<glm::dvec4> tangents;
  for (std::size_t v = 0; v < vertices; ++v) {
    const glm::dvec3 t = turn * glm::dvec3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    const double length = glm::length(t), w = values[4 * v + 3];
    if (!(length > 0.0) || !std::isfinite(length))
      reader.fail(where, "tangent " + std::to_string(v) + " is zero or not finite");
    // The glTF validator's tolerance on unit lengths.
    if (!(std::abs(std::abs(w) - 1.0) <= 4e-3))
      reader.fail(where, "tangent " + std::to_string(v) + " has w " + formatNumber(w) + "; it must be 1 or -1");
    tangents.push_back(glm::dvec4(t / length, w < 0.0 ? -mirror : mirror));
  }
  return tangents;
}

bool completeTangents(ControlCage& cage, int set) {
  const std::vector<glm::dvec2>& texcoords = set == 1 ? cage.texcoords1 : cage.texcoords;
  const std::vector<int>& corners = set == 1 ? cage.faceVertexTexcoords1 : cage.faceVertexTexcoords;
  if (corners.empty()) return false;
  std::vector<TangentCorner> mesh;
  for (std::size_t c = 0; c < cage.faceVertexIndices.size(); ++c) {
    const glm::dvec2 uv = texcoords[std::size_t(corners[c])];
    // glTF's v runs down the image, MikkTSpace's up it.
    mesh.push_back({cage.positions[std::size_t(cage.faceVertexIndices[c])], cage.faceVertexNormals[c],
                    glm::dvec2(uv.x, 1.0 - uv.y)});
  }
  const std::vector<glm::dvec4> generated = mikktspaceTangents(mesh);
  for (std::size_t c = 0; c < generated.size(); ++c)
    if (cage.faceVertexTangents[c].w == 0.0) cage.faceVertexTangents[c] = generated[c];
  return true;
}

}  // namespace facet::scene::detail
