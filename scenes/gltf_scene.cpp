// glTF 2.0 scenes through tinygltf; the mapping to facet's scene is
// docs/scene-format.md, "glTF 2.0".
#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <tuple>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"

namespace facet::scene {
namespace {

// glTF's primitive modes (points and lines below these have no surface).
constexpr int kTriangles = 4;
constexpr int kTriangleStrip = 5;
constexpr int kTriangleFan = 6;

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, std::string source) : model_(model), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& rule) const {
    throw InputError(source_, 0, where, rule);
  }

  // Element `i` of an accessor as doubles (components × count), range-checked.
  std::vector<double> read(int accessorIndex, const std::string& where, std::size_t expectedComponents) const {
    if (accessorIndex < 0 || std::size_t(accessorIndex) >= model_.accessors.size())
      fail(where, "accessor index out of range");
    const tinygltf::Accessor& a = model_.accessors[std::size_t(accessorIndex)];
    const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type)));
    if (components != expectedComponents)
      fail(where, "expected " + std::to_string(expectedComponents) + " components per element, found " +
                      std::to_string(components));
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= model_.bufferViews.size())
      fail(where, "accessor has no buffer view (sparse accessors are not supported)");
    const tinygltf::BufferView& view = model_.bufferViews[std::size_t(a.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size()) fail(where, "buffer index out of range");
    const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
    const int componentBytes = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
    if (componentBytes <= 0) fail(where, "unknown component type " + std::to_string(a.componentType));
    const std::size_t elementBytes = components * std::size_t(componentBytes);
    const std::size_t stride = view.byteStride ? view.byteStride : elementBytes;
    const std::size_t begin = view.byteOffset + a.byteOffset;
    if (a.count > 0 && (begin + (a.count - 1) * stride + elementBytes > view.byteOffset + view.byteLength ||
                        view.byteOffset + view.byteLength > data.size()))
      fail(where, "accessor reads past the end of its buffer");
    std::vector<double> out;
    out.reserve(a.count * components);
    for (std::size_t i = 0; i < a.count; ++i) {
      const unsigned char* element = data.data() + begin + i * stride;
      for (std::size_t c = 0; c < components; ++c)
        out.push_back(component(element + c * std::size_t(componentBytes), a.componentType));
    }
    return out;
  }

 private:
  static double component(const unsigned char* p, int type) {
    switch (type) {
      case 5120: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return v;
      }
      case 5121:
        return *p;
      case 5122: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      case 5123: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      case 5125: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
      }
      default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
      }
    }
  }

  const tinygltf::Model& model_;
  std::string source_;
};

glm::dmat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[std::size_t(4 * c + r)];
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m = glm::translate(m, {node.translation[0], node.translation[1], node.translation[2]});
  if (node.rotation.size() == 4)
    m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  if (node.scale.size() == 3) m = glm::scale(m, {node.scale[0], node.scale[1], node.scale[2]});
  return m;
}

materials::Material toMaterial(const tinygltf::Material& gltf, std::size_t index) {
  const auto& pbr = gltf.pbrMetallicRoughness;
  glm::dvec3 base(1.0);
  if (pbr.baseColorFactor.size() >= 3) base = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
  const double metallic = std::clamp(pbr.metallicFactor, 0.0, 1.0);
  const double roughness = std::clamp(pbr.roughnessFactor, 0.0, 1.0);
  materials::Material m = defaultMaterial();
  m.name = gltf.name.empty() ? "material " + std::to_string(index) : gltf.name;
  m.diffuse = base * (1.0 - metallic);
  m.f0 = glm::mix(glm::dvec3(0.04), base, metallic);
  m.alpha = roughness * roughness;
  return m;
}

Light toLight(const tinygltf::Light& gltf, const glm::dmat4& world, const GltfReader& reader,
              const std::string& where) {
  Light light;
  glm::dvec3 color(1.0);
  if (gltf.color.size() == 3) color = {gltf.color[0], gltf.color[1], gltf.color[2]};
  if (gltf.intensity < 0) reader.fail(where, "light intensity must not be negative");
  light.color = color * gltf.intensity / std::numbers::pi;
  light.position = glm::dvec3(world[3]);
  light.direction = glm::normalize(glm::dvec3(world * glm::dvec4(0, 0, -1, 0)));
  if (gltf.type == "directional") {
    light.type = LightType::Directional;
  } else if (gltf.type == "point") {
    light.type = LightType::Point;
  } else if (gltf.type == "spot") {
    light.type = LightType::Spot;
    light.innerConeDegrees = glm::degrees(gltf.spot.innerConeAngle);
    light.outerConeDegrees = glm::degrees(gltf.spot.outerConeAngle);
  } else {
    reader.fail(where, "unknown light type '" + gltf.type + "'");
  }
  return light;
}

// Which vertices of a primitive's list make its triangle `t`, in the glTF 2.0
// specification's order (3.7.2.1): a strip swaps the last two of every other
// triangle so that all keep one winding, a fan turns about the first vertex.
std::array<std::size_t, 3> triangleCorners(int mode, std::size_t t) {
  switch (mode) {
    case kTriangleStrip:
      return {t, t + 1 + t % 2, t + 2 - t % 2};
    case kTriangleFan:
      return {t + 1, t + 2, 0};
    default:
      return {3 * t, 3 * t + 1, 3 * t + 2};
  }
}

std::size_t triangleCount(int mode, std::size_t vertices, const GltfReader& reader, const std::string& where) {
  if (mode == kTriangles) {
    if (vertices % 3 != 0) reader.fail(where, "triangle index count is not a multiple of 3");
    return vertices / 3;
  }
  if (mode != kTriangleStrip && mode != kTriangleFan)
    reader.fail(where, "mode " + std::to_string(mode) +
                           " has no surface (expected TRIANGLES 4, TRIANGLE_STRIP 5 or TRIANGLE_FAN 6)");
  if (vertices < 3)
    reader.fail(where, std::string(mode == kTriangleStrip ? "a triangle strip" : "a triangle fan") +
                           " needs at least 3 vertices, has " + std::to_string(vertices));
  return vertices - 2;
}

// Adds the primitives of one mesh instance as one welded cage, with its
// NORMALs per face corner when every primitive has them (shading normals of
// the mesh as authored).
ControlCage toCage(const tinygltf::Mesh& mesh, const glm::dmat4& world, const GltfReader& reader,
                   const std::string& where) {
  ControlCage cage;
  cage.source = where;
  std::map<std::tuple<double, double, double>, int> welded;
  const bool normals = std::all_of(mesh.primitives.begin(), mesh.primitives.end(), [](const tinygltf::Primitive& p) {
    return p.attributes.count("NORMAL") != 0;
  });
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    const std::string at = where + ".primitives[" + std::to_string(p) + "]";
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) reader.fail(at, "has no POSITION attribute");
    const std::vector<double> xyz = reader.read(position->second, at + ".POSITION", 3);
    std::vector<int> remap(xyz.size() / 3);
    for (std::size_t v = 0; v < remap.size(); ++v) {
      const glm::dvec3 p3 = glm::dvec3(world * glm::dvec4(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0));
      if (!std::isfinite(p3.x) || !std::isfinite(p3.y) || !std::isfinite(p3.z))
        reader.fail(at, "POSITION " + std::to_string(v) + " is not finite");
      auto [it, inserted] = welded.try_emplace({p3.x, p3.y, p3.z}, cage.vertexCount());
      if (inserted) cage.positions.push_back(p3);
      remap[v] = it->second;
    }
    std::vector<glm::dvec3> vertexNormals;
    if (normals) {
      const std::vector<double> n = reader.read(primitive.attributes.at("NORMAL"), at + ".NORMAL", 3);
      if (n.size() != xyz.size()) reader.fail(at, "NORMAL and POSITION have different counts");
      for (std::size_t v = 0; v < n.size() / 3; ++v) {
        const glm::dvec3 transformed = normalMatrix * glm::dvec3(n[3 * v], n[3 * v + 1], n[3 * v + 2]);
        const double length = glm::length(transformed);
        if (!(length > 0.0) || !std::isfinite(length))
          reader.fail(at, "NORMAL " + std::to_string(v) + " is zero or not finite");
        vertexNormals.push_back(transformed / length);
      }
    }
    std::vector<double> indices;
    if (primitive.indices >= 0) {
      indices = reader.read(primitive.indices, at + ".indices", 1);
    } else {
      for (std::size_t v = 0; v < remap.size(); ++v) indices.push_back(double(v));
    }
    const std::size_t triangles = triangleCount(primitive.mode, indices.size(), reader, at);
    for (std::size_t t = 0; t < triangles; ++t) {
      int corners[3];
      std::size_t vertices[3];
      const std::array<std::size_t, 3> slots = triangleCorners(primitive.mode, t);
      for (int c = 0; c < 3; ++c) {
        const double index = indices[slots[std::size_t(c)]];
        if (index < 0 || index >= double(remap.size()))
          reader.fail(at, "index " + std::to_string(std::size_t(index)) + " is out of range");
        vertices[c] = std::size_t(index);
        corners[c] = remap[vertices[c]];
      }
      // A triangle with two corners at one position (strips join through
      // such triangles) has no area and would only add spurious topology.
      if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) continue;
      cage.faceVertexCounts.push_back(3);
      cage.faceVertexIndices.insert(cage.faceVertexIndices.end(), corners, corners + 3);
      if (normals)
        for (std::size_t vertex : vertices) cage.faceVertexNormals.push_back(vertexNormals[vertex]);
    }
  }
  if (cage.faceCount() == 0) reader.fail(where, "has no faces");
  if (glm::determinant(glm::dmat3(world)) < 0) {
    for (std::size_t f = 0; f < cage.faceVertexIndices.size(); f += 3) {
      std::swap(cage.faceVertexIndices[f + 1], cage.faceVertexIndices[f + 2]);
      if (normals) std::swap(cage.faceVertexNormals[f + 1], cage.faceVertexNormals[f + 2]);
    }
  }
  return cage;
}

}  // namespace

Scene loadGltfScene(const std::filesystem::path& path) {
  const std::string source = path.string();
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  const bool binary = path.extension() == ".glb";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, source)
                         : loader.LoadASCIIFromFile(&model, &error, &warning, source);
  if (!ok) throw InputError(source, 0, "cannot load glTF", error.empty() ? "unknown tinygltf error" : error);
  const GltfReader reader(model, source);

  Scene scene;
  scene.source = path;
  for (std::size_t i = 0; i < model.materials.size(); ++i) scene.materials.push_back(toMaterial(model.materials[i], i));
  const int defaultMaterialIndex = int(scene.materials.size());
  scene.materials.push_back(defaultMaterial());

  std::optional<Camera> camera;
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    roots = model.scenes.at(std::size_t(sceneIndex)).nodes;
  } else {
    for (std::size_t i = 0; i < model.nodes.size(); ++i) roots.push_back(int(i));
  }
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (int root : roots) stack.push_back({root, glm::dmat4(1.0)});
  std::size_t visited = 0;
  while (!stack.empty()) {
    auto [index, parent] = stack.back();
    stack.pop_back();
    if (index < 0 || std::size_t(index) >= model.nodes.size())
      reader.fail("nodes", "node index " + std::to_string(index) + " out of range");
    if (++visited > 4 * model.nodes.size() + 4) reader.fail("nodes", "the node hierarchy has a cycle");
    const tinygltf::Node& node = model.nodes[std::size_t(index)];
    const std::string where = "nodes[" + std::to_string(index) + "]";
    const glm::dmat4 world = parent * localTransform(node);
    if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= model.meshes.size()) reader.fail(where, "mesh index out of range");
      const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
      Object object;
      object.name = mesh.name.empty() ? where : mesh.name;
      object.cage = toCage(mesh, world, reader, "meshes[" + std::to_string(node.mesh) + "]");
      object.subdivision = Subdivision::None;
      const int material = mesh.primitives.empty() ? -1 : mesh.primitives.front().material;
      object.material = material >= 0 && material < defaultMaterialIndex ? material : defaultMaterialIndex;
      scene.objects.push_back(std::move(object));
    }
    if (node.camera >= 0 && !camera) {
      if (std::size_t(node.camera) >= model.cameras.size()) reader.fail(where, "camera index out of range");
      const tinygltf::Camera& c = model.cameras[std::size_t(node.camera)];
      if (c.type == "perspective") {
        Camera view;
        view.eye = glm::dvec3(world[3]);
        view.target = view.eye + glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
        view.up = glm::normalize(glm::dvec3(world * glm::dvec4(0, 1, 0, 0)));
        view.verticalFovDegrees = glm::degrees(c.perspective.yfov);
        camera = view;
      }
    }
    if (auto light = node.extensions.find("KHR_lights_punctual");
        light != node.extensions.end() && light->second.Has("light")) {
      const int lightIndex = light->second.Get("light").GetNumberAsInt();
      if (lightIndex < 0 || std::size_t(lightIndex) >= model.lights.size())
        reader.fail(where, "KHR_lights_punctual light index out of range");
      scene.lights.push_back(toLight(model.lights[std::size_t(lightIndex)], world, reader, where));
    }
    for (int child : node.children) stack.push_back({child, world});
  }
  if (scene.objects.empty()) throw InputError(source, 0, "no meshes", "the glTF scene has no node with a mesh");
  scene.camera = camera ? *camera : frameBounds(cageBounds(scene));
  if (scene.lights.empty()) scene.lights.push_back(defaultKeyLight(scene.camera));
  return scene;
}

}  // namespace facet::scene
