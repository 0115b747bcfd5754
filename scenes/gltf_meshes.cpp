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
constexpr ElementFormat kColor3{
    3,
    {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
    "VEC3 or VEC4 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT",
    true,
    true};
constexpr ElementFormat kColor4{4, kColor3.componentTypes, kColor3.name, true, true};
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

// A face-varying attribute of the glTF mesh (TEXCOORD_n, COLOR_0) as a
// cage channel: the values of one primitive, `size` per vertex, and the
// distinct values per cage vertex so that corners sharing both share one.
struct Attribute {
  const char* name;
  const ElementFormat* format;  // nullptr: kColor3 or kColor4 by the accessor's type
  std::size_t size;
  bool present = false;
  std::vector<double> perVertex;
  std::map<std::tuple<int, double, double, double>, int> distinct;

  std::vector<double> read(const tinygltf::Primitive& primitive, std::size_t vertices, const GltfReader& reader,
                           const std::string& at) {
    const int accessor = primitive.attributes.at(name);
    const std::string where = at + "." + name;
    const ElementFormat& f = format ? *format : reader.components(accessor, where) == 4 ? kColor4 : kColor3;
    std::vector<double> values = reader.read(accessor, where, f);
    if (values.size() / f.components != vertices)
      reader.fail(at, std::string(name) + " and POSITION have different counts");
    std::vector<double> out;
    for (std::size_t v = 0; v < vertices; ++v)
      for (std::size_t c = 0; c < size; ++c) {
        const double x = values[v * f.components + c];
        if (!std::isfinite(x)) reader.fail(at, std::string(name) + " " + std::to_string(v) + " is not finite");
        // A colour past [0, 1] would make the base colour reflect more than it receives.
        if (!format && !(x >= 0.0 && x <= 1.0))
          reader.fail(
              at, std::string(name) + " " + std::to_string(v) + " has a component outside [0, 1], " + formatNumber(x));
        out.push_back(x);
      }
    return out;
  }

  // The value index of the corner of cage vertex `corner` at primitive vertex `vertex`.
  template <class Value>
  int add(int corner, std::size_t vertex, std::vector<Value>& values) {
    double x[3] = {0.0, 0.0, 0.0};
    for (std::size_t c = 0; c < size; ++c) x[c] = perVertex[size * vertex + c];
    auto [it, inserted] = distinct.try_emplace({corner, x[0], x[1], x[2]}, int(values.size()));
    if (inserted) {
      Value value;
      for (std::size_t c = 0; c < size; ++c) value[int(c)] = x[c];
      values.push_back(value);
    }
    return it->second;
  }
};

}  // namespace

std::vector<double> morphWeights(const tinygltf::Node& node, const tinygltf::Mesh& mesh, const GltfReader& reader,
                                 const std::string& nodeWhere, const std::string& meshWhere) {
  const bool fromNode = !node.weights.empty();
  const std::vector<double>& stated = fromNode ? node.weights : mesh.weights;
  const std::string field = (fromNode ? nodeWhere : meshWhere) + ".weights";
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const std::size_t targets = mesh.primitives[p].targets.size();
    if (!stated.empty() && stated.size() != targets)
      reader.fail(field, "has " + std::to_string(stated.size()) + " weights, but " + meshWhere + ".primitives[" +
                             std::to_string(p) + "] has " + std::to_string(targets) + " morph targets");
    if (targets != mesh.primitives.front().targets.size())
      reader.fail(meshWhere + ".primitives[" + std::to_string(p) + "].targets",
                  "every primitive of a mesh must have as many morph targets as the first");
  }
  for (double w : stated)
    if (!std::isfinite(w)) reader.fail(field, "must be finite numbers, has " + formatNumber(w));
  if (!stated.empty()) return stated;
  return std::vector<double>(mesh.primitives.empty() ? 0 : mesh.primitives.front().targets.size(), 0.0);
}

void morph(std::vector<double>& values, const tinygltf::Primitive& primitive, const char* attribute,
           const std::vector<double>& weights, const GltfReader& reader, const std::string& at) {
  for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
    const auto delta = primitive.targets[t].find(attribute);
    if (weights[t] == 0.0 || delta == primitive.targets[t].end()) continue;
    const std::string where = at + ".targets[" + std::to_string(t) + "]." + attribute;
    const std::vector<double> d = reader.read(delta->second, where, kFloatVec3);
    if (d.size() != values.size())
      reader.fail(where, std::string("has another count than the primitive's ") + attribute);
    for (std::size_t i = 0; i < d.size(); ++i) values[i] += weights[t] * d[i];
  }
}

namespace {

// A primitive's NORMALs, moved by its morph targets by `weights` and turned
// into the world by `world`'s normal matrix; each checked nonzero and finite.
std::vector<glm::dvec3> primitiveNormals(const tinygltf::Primitive& primitive, std::size_t vertices,
                                         const glm::dmat4& world, const std::vector<double>& weights,
                                         const GltfReader& reader, const std::string& at) {
  std::vector<double> n = reader.read(primitive.attributes.at("NORMAL"), at + ".NORMAL", kFloatVec3);
  if (n.size() != 3 * vertices) reader.fail(at, "NORMAL and POSITION have different counts");
  morph(n, primitive, "NORMAL", weights, reader, at);
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  std::vector<glm::dvec3> normals;
  for (std::size_t v = 0; v < vertices; ++v) {
    const glm::dvec3 transformed = normalMatrix * glm::dvec3(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
    const double length = glm::length(transformed);
    if (!(length > 0.0) || !std::isfinite(length))
      reader.fail(at, "NORMAL " + std::to_string(v) + " is zero or not finite");
    normals.push_back(transformed / length);
  }
  return normals;
}

// Under a mirroring node every triangle turns the other way: its last two
// corners swap, with each per-corner attribute.
void reverseMirroredWinding(ControlCage& cage) {
  for (std::size_t f = 0; f < cage.faceVertexIndices.size(); f += 3) {
    std::swap(cage.faceVertexIndices[f + 1], cage.faceVertexIndices[f + 2]);
    if (!cage.faceVertexNormals.empty()) std::swap(cage.faceVertexNormals[f + 1], cage.faceVertexNormals[f + 2]);
    if (!cage.faceVertexTangents.empty()) std::swap(cage.faceVertexTangents[f + 1], cage.faceVertexTangents[f + 2]);
    for (std::vector<int>* corners : {&cage.faceVertexTexcoords, &cage.faceVertexTexcoords1, &cage.faceVertexColors})
      if (!corners->empty()) std::swap((*corners)[f + 1], (*corners)[f + 2]);
  }
}

}  // namespace

ControlCage toCage(const tinygltf::Mesh& mesh, const std::vector<std::size_t>& primitives, const glm::dmat4& world,
                   const std::vector<double>& weights, std::optional<int> tangentSet, const GltfReader& reader,
                   const std::string& where) {
  ControlCage cage;
  cage.source = where;
  std::map<std::tuple<double, double, double>, int> welded;
  const auto everyPrimitiveHas = [&](const char* attribute) {
    return std::all_of(primitives.begin(), primitives.end(),
                       [&](std::size_t p) { return mesh.primitives[p].attributes.count(attribute) != 0; });
  };
  const bool normals = everyPrimitiveHas("NORMAL");
  const bool tangents = normals && tangentSet.has_value();
  if (tangentSet && !normals && std::any_of(primitives.begin(), primitives.end(), [&](std::size_t p) {
        return mesh.primitives[p].attributes.count("TANGENT") != 0;
      }))
    reader.warn(where,
                "TANGENT is not read: not every primitive of its material has NORMAL, so the object is "
                "shaded flat and its tangents are dP/du of the texture coordinates");
  // COLOR_0's alpha is not read: RGB multiplies the base colour.
  Attribute uv0{"TEXCOORD_0", &kTexcoord, 2}, uv1{"TEXCOORD_1", &kTexcoord, 2}, color{"COLOR_0", nullptr, 3};
  for (Attribute* a : {&uv0, &uv1, &color}) a->present = everyPrimitiveHas(a->name);
  if (!color.present)
    for (std::size_t p : primitives)
      if (mesh.primitives[p].attributes.count("COLOR_0"))
        reader.warn(where + ".primitives[" + std::to_string(p) + "].attributes.COLOR_0",
                    "not every primitive of its material has COLOR_0, so the object's vertex colours are not read");
  for (std::size_t p : primitives) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    const std::string at = where + ".primitives[" + std::to_string(p) + "]";
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) reader.fail(at, "has no POSITION attribute");
    std::vector<double> xyz = reader.read(position->second, at + ".POSITION", kFloatVec3);
    morph(xyz, primitive, "POSITION", weights, reader, at);
    std::vector<int> remap(xyz.size() / 3, -1);
    const std::vector<glm::dvec3> vertexNormals =
        normals ? primitiveNormals(primitive, remap.size(), world, weights, reader, at) : std::vector<glm::dvec3>{};
    for (Attribute* a : {&uv0, &uv1, &color})
      if (a->present) a->perVertex = a->read(primitive, remap.size(), reader, at);
    // w 0: MikkTSpace's, once the whole cage is known.
    const std::vector<glm::dvec4> vertexTangents =
        tangents && primitive.attributes.count("TANGENT")
            ? primitiveTangents(primitive, remap.size(), world, weights, reader, at)
            : std::vector<glm::dvec4>(tangents ? remap.size() : 0, glm::dvec4(0.0));
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
      for (std::size_t vertex : vertices) {
        if (normals) cage.faceVertexNormals.push_back(vertexNormals[vertex]);
        if (tangents) cage.faceVertexTangents.push_back(vertexTangents[vertex]);
      }
      for (int c = 0; c < 3; ++c) {
        if (uv0.present) cage.faceVertexTexcoords.push_back(uv0.add(corners[c], vertices[c], cage.texcoords));
        if (uv1.present) cage.faceVertexTexcoords1.push_back(uv1.add(corners[c], vertices[c], cage.texcoords1));
        if (color.present) cage.faceVertexColors.push_back(color.add(corners[c], vertices[c], cage.colors));
      }
    }
  }
  if (glm::determinant(glm::dmat3(world)) < 0) reverseMirroredWinding(cage);
  const auto authored = [](const glm::dvec4& t) { return t.w != 0.0; };
  if (!std::all_of(cage.faceVertexTangents.begin(), cage.faceVertexTangents.end(), authored) &&
      !completeTangents(cage, *tangentSet)) {
    // Without the coordinates there is nothing to generate from: shading takes the parametric tangent.
    if (std::any_of(cage.faceVertexTangents.begin(), cage.faceVertexTangents.end(), authored))
      reader.warn(where, "TANGENT is not read: some of its primitives lack it, and without TEXCOORD_" +
                             std::to_string(*tangentSet) + " theirs cannot be generated");
    cage.faceVertexTangents.clear();
  }
  return cage;
}

}  // namespace facet::scene::detail
