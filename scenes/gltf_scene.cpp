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
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <string_view>
#include <tuple>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/texture.h"
#include "scenes/value_rules.h"

namespace facet::scene {
namespace {

// tinygltf's JSON parser recurses once per nested array or object, so deep
// enough nesting overflows the stack; glTF itself nests fewer than 20 levels.
constexpr int kMaxJsonNesting = 512;

// What an accessor's elements must be, from the glTF 2.0 specification's
// tables of mesh attributes and indices (3.7.2.1).
struct ElementFormat {
  std::size_t components;
  std::array<int, 3> componentTypes;  // unused slots repeat the first
  const char* name;
  bool normalizable = false;  // integer components may be normalized
};
constexpr ElementFormat kFloatVec3{
    3, {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_FLOAT}, "FLOAT VEC3"};
constexpr ElementFormat kTexcoord{
    2, {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
    "VEC2 of FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT", true};
constexpr ElementFormat kVertexIndex{1,
                                     {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                     "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT"};

// Whether `count` elements of `elementBytes`, `stride` apart from byte
// `begin`, end by byte `end`, in arithmetic that cannot wrap around.
bool elementsFit(std::size_t begin, std::size_t count, std::size_t stride, std::size_t elementBytes, std::size_t end) {
  if (count == 0) return true;
  if (begin > end || elementBytes > end - begin) return false;
  return count - 1 <= (end - begin - elementBytes) / stride;
}

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, std::string source) : model_(model), source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& rule) const {
    throw InputError(source_, 0, where, rule);
  }

  // The elements of an accessor as doubles (components × count), checked
  // against `format` and against the bounds of its buffer; normalized
  // integers of a format that allows them map to [0, 1] (glTF 2.0, 3.11).
  std::vector<double> read(int accessorIndex, const std::string& where, const ElementFormat& format) const {
    if (accessorIndex < 0 || std::size_t(accessorIndex) >= model_.accessors.size())
      fail(where, "accessor index out of range");
    const tinygltf::Accessor& a = model_.accessors[std::size_t(accessorIndex)];
    const std::string accessor = "accessors[" + std::to_string(accessorIndex) + "]";
    const std::size_t components = std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(a.type)));
    if (components != format.components || std::find(format.componentTypes.begin(), format.componentTypes.end(),
                                                     a.componentType) == format.componentTypes.end())
      fail(where, accessor + " must be " + format.name + ", is componentType " + std::to_string(a.componentType) +
                      " with " + std::to_string(components) + " components");
    if (a.bufferView < 0 || std::size_t(a.bufferView) >= model_.bufferViews.size())
      fail(where, "accessor has no buffer view (sparse accessors are not supported)");
    const tinygltf::BufferView& view = model_.bufferViews[std::size_t(a.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size()) fail(where, "buffer index out of range");
    const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
    const std::size_t componentBytes = std::size_t(tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType)));
    const std::size_t elementBytes = components * componentBytes;
    const std::size_t stride = view.byteStride ? view.byteStride : elementBytes;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset ||
        !elementsFit(a.byteOffset, a.count, stride, elementBytes, view.byteLength))
      fail(where, accessor + " (count " + std::to_string(a.count) + ", byteOffset " + std::to_string(a.byteOffset) +
                      ", stride " + std::to_string(stride) + ") reads past the end of its buffer");
    const unsigned char* begin = data.data() + view.byteOffset + a.byteOffset;
    double range = 1.0;
    if (format.normalizable && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) range = 255;
    if (format.normalizable && a.normalized && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) range = 65535;
    std::vector<double> out;
    out.reserve(a.count * components);
    for (std::size_t i = 0; i < a.count; ++i) {
      const unsigned char* element = begin + i * stride;
      for (std::size_t c = 0; c < components; ++c)
        out.push_back(component(element + c * componentBytes, a.componentType) / range);
    }
    return out;
  }

 private:
  static double component(const unsigned char* p, int type) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
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

// The glTF sampler's codes (OpenGL's enums) as rules/texture/texture_sampling.h's.
TextureSampler toSampler(const tinygltf::Sampler& gltf, const std::string& where, const GltfReader& reader) {
  namespace t = rules::f64;
  TextureSampler sampler;
  auto wrap = [&](int mode, const char* field) {
    switch (mode) {
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return t::FACET_WRAP_REPEAT;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return t::FACET_WRAP_MIRRORED_REPEAT;
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return t::FACET_WRAP_CLAMP_TO_EDGE;
    }
    reader.fail(where + field, "unknown wrap mode " + std::to_string(mode) + " (expected 10497, 33648 or 33071)");
  };
  sampler.wrapS = wrap(gltf.wrapS, ".wrapS");
  sampler.wrapT = wrap(gltf.wrapT, ".wrapT");
  if (gltf.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST)
    sampler.magFilter = t::FACET_FILTER_NEAREST;
  else if (gltf.magFilter != -1 && gltf.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
    reader.fail(where + ".magFilter", "unknown filter " + std::to_string(gltf.magFilter) + " (expected 9728 or 9729)");
  // minFilter: the filter within a level and the mip mode, by OpenGL's codes.
  struct MinFilter {
    int code;
    std::uint32_t texelFilter, mipMode;
  };
  const MinFilter minFilters[] = {
      {TINYGLTF_TEXTURE_FILTER_NEAREST, t::FACET_FILTER_NEAREST, t::FACET_MIP_NONE},
      {TINYGLTF_TEXTURE_FILTER_LINEAR, t::FACET_FILTER_LINEAR, t::FACET_MIP_NONE},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST, t::FACET_FILTER_NEAREST, t::FACET_MIP_NEAREST},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST, t::FACET_FILTER_LINEAR, t::FACET_MIP_NEAREST},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR, t::FACET_FILTER_NEAREST, t::FACET_MIP_LINEAR},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR, t::FACET_FILTER_LINEAR, t::FACET_MIP_LINEAR}};
  if (gltf.minFilter != -1) {
    const auto found = std::find_if(std::begin(minFilters), std::end(minFilters),
                                    [&](const MinFilter& f) { return f.code == gltf.minFilter; });
    if (found == std::end(minFilters))
      reader.fail(where + ".minFilter",
                  "unknown filter " + std::to_string(gltf.minFilter) + " (expected 9728, 9729 or 9984 to 9987)");
    sampler.minFilter = found->texelFilter;
    sampler.mipMode = found->mipMode;
  }
  return sampler;
}

// The scene's textures, converted from the glTF file's as materials use
// them: one per glTF texture and encoding.
class TextureTable {
 public:
  TextureTable(const tinygltf::Model& model, const GltfReader& reader, std::vector<Texture>& textures)
      : model_(model), reader_(reader), textures_(textures) {}

  // The slot of the texture info at field `where`: texture `index` with its extensions.
  materials::TextureSlot slot(const tinygltf::ExtensionMap& extensions, int index, int texCoord,
                              TextureEncoding encoding, const std::string& where) {
    materials::TextureSlot slot;
    if (index < 0) return slot;
    if (std::size_t(index) >= model_.textures.size())
      reader_.fail(where + ".index", "texture index " + std::to_string(index) + " out of range (the file has " +
                                         std::to_string(model_.textures.size()) + " textures)");
    if (auto found = extensions.find("KHR_texture_transform"); found != extensions.end()) {
      const tinygltf::Value& transform = found->second;
      const std::string at = where + ".extensions.KHR_texture_transform";
      slot.offset = pair(transform, "offset", at, glm::dvec2(0.0));
      slot.scale = pair(transform, "scale", at, glm::dvec2(1.0));
      if (transform.Has("rotation")) slot.rotation = number(transform.Get("rotation"), at + ".rotation");
      if (transform.Has("texCoord")) texCoord = int(number(transform.Get("texCoord"), at + ".texCoord"));
    }
    if (texCoord != 0)
      reader_.fail(where + ".texCoord", "only TEXCOORD_0 is read, not TEXCOORD_" + std::to_string(texCoord));
    auto [cached, fresh] = cache_.try_emplace({index, encoding}, int(textures_.size()));
    if (fresh) textures_.push_back(convert(index, encoding));
    slot.texture = cached->second;
    return slot;
  }

 private:
  double number(const tinygltf::Value& value, const std::string& where) const {
    if (!value.IsNumber()) reader_.fail(where, "must be a number");
    const double x = value.GetNumberAsDouble();
    if (!std::isfinite(x)) reader_.fail(where, "must be finite");
    return x;
  }

  glm::dvec2 pair(const tinygltf::Value& transform, const char* key, const std::string& at, glm::dvec2 fallback) const {
    if (!transform.Has(key)) return fallback;
    const tinygltf::Value& value = transform.Get(key);
    const std::string where = at + "." + key;
    if (!value.IsArray() || value.ArrayLen() != 2) reader_.fail(where, "must be an array of 2 numbers");
    return {number(value.Get(0), where + "[0]"), number(value.Get(1), where + "[1]")};
  }

  Texture convert(int index, TextureEncoding encoding) const {
    const tinygltf::Texture& gltf = model_.textures[std::size_t(index)];
    const std::string where = "textures[" + std::to_string(index) + "]";
    if (gltf.source < 0 || std::size_t(gltf.source) >= model_.images.size())
      reader_.fail(where + ".source", "image index " + std::to_string(gltf.source) + " out of range (the file has " +
                                          std::to_string(model_.images.size()) + " images)");
    TextureSampler sampler;
    if (gltf.sampler >= 0) {
      if (std::size_t(gltf.sampler) >= model_.samplers.size())
        reader_.fail(where + ".sampler", "sampler index " + std::to_string(gltf.sampler) + " out of range");
      sampler = toSampler(model_.samplers[std::size_t(gltf.sampler)], "samplers[" + std::to_string(gltf.sampler) + "]",
                          reader_);
    }
    const tinygltf::Image& image = model_.images[std::size_t(gltf.source)];
    const std::string imageWhere = "images[" + std::to_string(gltf.source) + "]";
    const std::string name = image.uri.empty() ? imageWhere : image.uri;
    // tinygltf keeps an external image it cannot open as its uri alone.
    if (image.image.empty()) reader_.fail(imageWhere, "cannot read the image '" + name + "' (no such file)");
    if (image.width > kMaxTextureSize || image.height > kMaxTextureSize)
      reader_.fail(imageWhere, "an image must be at most " + std::to_string(kMaxTextureSize) + " x " +
                                   std::to_string(kMaxTextureSize) + ", is " + std::to_string(image.width) + " x " +
                                   std::to_string(image.height));
    const std::size_t values = std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.component);
    const std::size_t bytes = image.bits == 16 ? 2 : 1;
    if (image.bits != 8 && image.bits != 16) reader_.fail(imageWhere, "only 8- and 16-bit images are read");
    if (image.image.size() != values * bytes) reader_.fail(imageWhere, "the decoded size differs from the image's");
    std::vector<float> channels(values);
    for (std::size_t i = 0; i < values; ++i) {
      std::uint16_t wide = 0;
      if (bytes == 2) std::memcpy(&wide, &image.image[2 * i], 2);
      channels[i] = bytes == 2 ? float(wide) / 65535.0f : float(image.image[i]) / 255.0f;
    }
    return makeTexture(name, image.width, image.height, image.component, channels, encoding, sampler);
  }

  const tinygltf::Model& model_;
  const GltfReader& reader_;
  std::vector<Texture>& textures_;
  std::map<std::pair<int, TextureEncoding>, int> cache_;
};

materials::Material toMaterial(const tinygltf::Material& gltf, std::size_t index, const GltfReader& reader,
                               TextureTable& textures) {
  const auto& pbr = gltf.pbrMetallicRoughness;
  const std::string material = "materials[" + std::to_string(index) + "]";
  const std::string where = material + ".pbrMetallicRoughness";
  for (double c : pbr.baseColorFactor)
    if (!(c >= 0.0 && c <= 1.0))
      reader.fail(where + ".baseColorFactor", "every component must be in [0, 1], is " + formatNumber(c));
  glm::dvec3 base(1.0);
  if (pbr.baseColorFactor.size() >= 3) base = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
  for (auto [field, value] :
       {std::pair{".metallicFactor", pbr.metallicFactor}, std::pair{".roughnessFactor", pbr.roughnessFactor}})
    if (const std::optional<std::string> rule = rangeRule(value, 0.0, 1.0)) reader.fail(where + field, *rule);
  const double metallic = pbr.metallicFactor;
  const double roughness = pbr.roughnessFactor;
  materials::Material m = defaultMaterial();
  m.name = gltf.name.empty() ? "material " + std::to_string(index) : gltf.name;
  m.diffuse = base * (1.0 - metallic);
  m.f0 = glm::mix(glm::dvec3(0.04), base, metallic);
  m.alpha = roughness * roughness;
  for (double c : gltf.emissiveFactor)
    if (!(c >= 0.0 && c <= 1.0))
      reader.fail(material + ".emissiveFactor", "every component must be in [0, 1], is " + formatNumber(c));
  if (gltf.emissiveFactor.size() == 3)
    m.emission = {gltf.emissiveFactor[0], gltf.emissiveFactor[1], gltf.emissiveFactor[2]};

  materials::MaterialTextures t;
  t.baseColor = base;
  t.metallic = metallic;
  t.roughness = roughness;
  const auto& b = pbr.baseColorTexture;
  t.baseColorTexture =
      textures.slot(b.extensions, b.index, b.texCoord, TextureEncoding::Srgb, where + ".baseColorTexture");
  const auto& mr = pbr.metallicRoughnessTexture;
  t.metallicRoughnessTexture =
      textures.slot(mr.extensions, mr.index, mr.texCoord, TextureEncoding::Linear, where + ".metallicRoughnessTexture");
  const auto& n = gltf.normalTexture;
  t.normalTexture =
      textures.slot(n.extensions, n.index, n.texCoord, TextureEncoding::Linear, material + ".normalTexture");
  t.normalScale = n.scale;
  const auto& o = gltf.occlusionTexture;
  t.occlusionTexture =
      textures.slot(o.extensions, o.index, o.texCoord, TextureEncoding::Linear, material + ".occlusionTexture");
  if (const std::optional<std::string> rule = rangeRule(o.strength, 0.0, 1.0))
    reader.fail(material + ".occlusionTexture.strength", *rule);
  t.occlusionStrength = o.strength;
  const auto& e = gltf.emissiveTexture;
  t.emissiveTexture =
      textures.slot(e.extensions, e.index, e.texCoord, TextureEncoding::Srgb, material + ".emissiveTexture");
  for (const materials::TextureSlot* s :
       {&t.baseColorTexture, &t.metallicRoughnessTexture, &t.normalTexture, &t.occlusionTexture, &t.emissiveTexture})
    if (s->texture >= 0) m.textures = t;
  return m;
}

// Light `index` of KHR_lights_punctual, placed by node `where`.
Light toLight(const tinygltf::Light& gltf, int index, const glm::dmat4& world, const GltfReader& reader,
              const std::string& where) {
  const std::string field = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
  Light light;
  glm::dvec3 color(1.0);
  if (gltf.color.size() == 3) color = {gltf.color[0], gltf.color[1], gltf.color[2]};
  if (hasNegativeComponent(color)) reader.fail(field + ".color", kNegativeColorRule);
  if (gltf.intensity < 0) reader.fail(where, "light intensity must not be negative");
  light.color = color * gltf.intensity / std::numbers::pi;
  light.position = glm::dvec3(world[3]);
  if (gltf.type == "directional") {
    light.type = LightType::Directional;
  } else if (gltf.type == "point") {
    light.type = LightType::Point;
  } else if (gltf.type == "spot") {
    light.type = LightType::Spot;
    const double inner = gltf.spot.innerConeAngle;
    const double outer = gltf.spot.outerConeAngle;
    if (!(inner >= 0.0 && inner < outer && outer <= std::numbers::pi / 2))
      reader.fail(field + ".spot", "must have 0 <= innerConeAngle < outerConeAngle <= pi/2, has " +
                                       formatNumber(inner) + " and " + formatNumber(outer));
    light.innerConeDegrees = glm::degrees(inner);
    light.outerConeDegrees = glm::degrees(outer);
  } else {
    reader.fail(where, "unknown light type '" + gltf.type + "'");
  }
  if (light.type != LightType::Point) {
    const glm::dvec3 direction(world * glm::dvec4(0, 0, -1, 0));
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length))
      reader.fail(where, "the node's matrix is singular, so light " + std::to_string(index) + " has no direction");
    light.direction = direction / length;
  }
  return light;
}

// Perspective camera `index`, placed by node `where` and its world matrix.
Camera toCamera(const tinygltf::Camera& gltf, int index, const glm::dmat4& world, const GltfReader& reader,
                const std::string& where) {
  const std::string field = "cameras[" + std::to_string(index) + "].perspective.yfov";
  Camera camera;
  camera.verticalFovDegrees = glm::degrees(gltf.perspective.yfov);
  if (const std::optional<std::string> rule = rangeRule(camera.verticalFovDegrees, kMinFovDegrees, kMaxFovDegrees))
    reader.fail(field, "in degrees, " + *rule);
  const glm::dvec3 forward(world * glm::dvec4(0, 0, -1, 0));
  const glm::dvec3 up(world * glm::dvec4(0, 1, 0, 0));
  camera.eye = glm::dvec3(world[3]);
  // The test of the command line's --eye, --target and --up, so that a camera
  // accepted here is accepted there.
  if (!std::isfinite(glm::length(camera.eye)) ||
      !(glm::length(glm::cross(forward, up)) > 1e-12 * glm::length(forward) * glm::length(up)))
    reader.fail(where, "the node's matrix is singular or not finite, so camera " + std::to_string(index) +
                           " has no view direction and up vector");
  camera.target = camera.eye + glm::normalize(forward);
  camera.up = glm::normalize(up);
  return camera;
}

// The roots of the scene to render, once the node hierarchy is checked to be
// the forest glTF requires (2.0, 3.5.3): a node has at most one parent, and a
// root has none and is listed once.
std::vector<int> sceneRoots(const tinygltf::Model& model, const GltfReader& reader) {
  const int nodes = int(model.nodes.size());
  std::vector<int> parent(model.nodes.size(), -1);
  for (int n = 0; n < nodes; ++n) {
    const std::string where = "nodes[" + std::to_string(n) + "].children";
    for (int child : model.nodes[std::size_t(n)].children) {
      if (child < 0 || child >= nodes) reader.fail(where, "node index " + std::to_string(child) + " out of range");
      int& childParent = parent[std::size_t(child)];
      if (childParent >= 0)
        reader.fail(where, "node " + std::to_string(child) + " is a child of node " + std::to_string(childParent) +
                               " too (a node has at most one parent)");
      childParent = n;
    }
  }
  std::vector<int> roots;
  if (model.scenes.empty()) {
    for (int n = 0; n < nodes; ++n)
      if (parent[std::size_t(n)] < 0) roots.push_back(n);
    return roots;
  }
  if (model.defaultScene < -1 || model.defaultScene >= int(model.scenes.size()))
    reader.fail("scene", "scene index " + std::to_string(model.defaultScene) + " out of range (the file has " +
                             std::to_string(model.scenes.size()) + " scenes)");
  const int sceneIndex = std::max(model.defaultScene, 0);
  const std::string where = "scenes[" + std::to_string(sceneIndex) + "].nodes";
  std::vector<bool> listed(model.nodes.size(), false);
  for (int root : model.scenes[std::size_t(sceneIndex)].nodes) {
    if (root < 0 || root >= nodes) reader.fail(where, "node index " + std::to_string(root) + " out of range");
    if (listed[std::size_t(root)]) reader.fail(where, "node " + std::to_string(root) + " is listed twice");
    if (parent[std::size_t(root)] >= 0)
      reader.fail(where, "node " + std::to_string(root) + " is a root and a child of node " +
                             std::to_string(parent[std::size_t(root)]));
    listed[std::size_t(root)] = true;
    roots.push_back(root);
  }
  return roots;
}

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

// Adds the primitives of one mesh instance as one welded cage, with its
// NORMALs per face corner when every primitive has them (shading normals of
// the mesh as authored), and likewise its TEXCOORD_0 as a face-varying
// channel: one value per welded vertex and coordinate, so corners that
// share both stay joined and the rest form seams.
ControlCage toCage(const tinygltf::Mesh& mesh, const glm::dmat4& world, const GltfReader& reader,
                   const std::string& where) {
  ControlCage cage;
  cage.source = where;
  std::map<std::tuple<double, double, double>, int> welded;
  std::map<std::tuple<int, double, double>, int> texcoordValues;
  const bool normals = std::all_of(mesh.primitives.begin(), mesh.primitives.end(),
                                   [](const tinygltf::Primitive& p) { return p.attributes.count("NORMAL") != 0; });
  const bool texcoords = std::all_of(mesh.primitives.begin(), mesh.primitives.end(),
                                     [](const tinygltf::Primitive& p) { return p.attributes.count("TEXCOORD_0") != 0; });
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = mesh.primitives[p];
    const std::string at = where + ".primitives[" + std::to_string(p) + "]";
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) reader.fail(at, "has no POSITION attribute");
    const std::vector<double> xyz = reader.read(position->second, at + ".POSITION", kFloatVec3);
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
    const std::size_t triangles = triangleCount(primitive.mode, indices.size(), reader, at);
    for (std::size_t t = 0; t < triangles; ++t) {
      int corners[3];
      std::size_t vertices[3];
      const std::array<std::size_t, 3> slots = triangleCorners(primitive.mode, t);
      for (int c = 0; c < 3; ++c) {
        const double index = indices[slots[std::size_t(c)]];
        if (index >= double(remap.size())) reader.fail(at, "index " + formatNumber(index) + " is out of range");
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
      for (int c = 0; texcoords && c < 3; ++c) {
        const double s = uv[2 * vertices[c]], t = uv[2 * vertices[c] + 1];
        auto [it, inserted] = texcoordValues.try_emplace({corners[c], s, t}, int(cage.texcoords.size()));
        if (inserted) cage.texcoords.push_back({s, t});
        cage.faceVertexTexcoords.push_back(it->second);
      }
    }
  }
  if (cage.faceCount() == 0) reader.fail(where, "has no faces");
  if (glm::determinant(glm::dmat3(world)) < 0) {
    for (std::size_t f = 0; f < cage.faceVertexIndices.size(); f += 3) {
      std::swap(cage.faceVertexIndices[f + 1], cage.faceVertexIndices[f + 2]);
      if (normals) std::swap(cage.faceVertexNormals[f + 1], cage.faceVertexNormals[f + 2]);
      if (texcoords) std::swap(cage.faceVertexTexcoords[f + 1], cage.faceVertexTexcoords[f + 2]);
    }
  }
  return cage;
}

// The deepest nesting of arrays and objects in `json`, outside strings,
// counted up to one past `limit`.
int jsonNesting(std::string_view json, int limit) {
  int depth = 0, deepest = 0;
  bool inString = false, escaped = false;
  for (char c : json) {
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) break;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

// The JSON chunk of a .glb file (glTF 2.0, 4.4): 12 bytes of header, then the
// chunk's length and type. A file too short for them is left to tinygltf.
std::string_view glbJson(std::string_view file) {
  if (file.size() < 20) return file;
  std::uint32_t length;
  std::memcpy(&length, file.data() + 12, 4);
  return file.substr(20, length);
}

}  // namespace

Scene loadGltfScene(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(source, 0, "cannot load glTF", "cannot open the file");
  const std::string file{std::istreambuf_iterator<char>(in), {}};
  const bool binary = path.extension() == ".glb";
  if (jsonNesting(binary ? glbJson(file) : file, kMaxJsonNesting) > kMaxJsonNesting)
    throw InputError(source, 0, "JSON nesting",
                     "arrays and objects nest deeper than " + std::to_string(kMaxJsonNesting) + " levels");
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  const std::string baseDir = path.parent_path().string();
  const bool ok =
      binary
          ? loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(file.data()),
                                        unsigned(file.size()), baseDir)
          : loader.LoadASCIIFromString(&model, &error, &warning, file.data(), unsigned(file.size()), baseDir);
  if (!ok) throw InputError(source, 0, "cannot load glTF", error.empty() ? "unknown tinygltf error" : error);
  const GltfReader reader(model, source);

  Scene scene;
  scene.source = path;
  TextureTable textures(model, reader, scene.textures);
  for (std::size_t i = 0; i < model.materials.size(); ++i)
    scene.materials.push_back(toMaterial(model.materials[i], i, reader, textures));
  const int defaultMaterialIndex = int(scene.materials.size());
  scene.materials.push_back(defaultMaterial());

  std::optional<Camera> camera;
  std::vector<std::pair<int, glm::dmat4>> stack;
  for (int root : sceneRoots(model, reader)) stack.push_back({root, glm::dmat4(1.0)});
  while (!stack.empty()) {
    auto [index, parent] = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[std::size_t(index)];
    const std::string where = "nodes[" + std::to_string(index) + "]";
    const glm::dmat4 world = parent * localTransform(node);
    if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= model.meshes.size()) reader.fail(where, "mesh index out of range");
      const tinygltf::Mesh& mesh = model.meshes[std::size_t(node.mesh)];
      const std::string meshWhere = "meshes[" + std::to_string(node.mesh) + "]";
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const int material = mesh.primitives[p].material;
        if (material < -1 || material >= defaultMaterialIndex)
          reader.fail(meshWhere + ".primitives[" + std::to_string(p) + "].material",
                      "material index " + std::to_string(material) + " out of range (the file has " +
                          std::to_string(defaultMaterialIndex) + " materials)");
      }
      Object object;
      object.name = mesh.name.empty() ? where : mesh.name;
      object.cage = toCage(mesh, world, reader, meshWhere);
      object.subdivision = Subdivision::None;
      const int material = mesh.primitives.empty() ? -1 : mesh.primitives.front().material;
      object.material = material >= 0 ? material : defaultMaterialIndex;
      scene.objects.push_back(std::move(object));
    }
    if (node.camera >= 0 && !camera) {
      if (std::size_t(node.camera) >= model.cameras.size()) reader.fail(where, "camera index out of range");
      const tinygltf::Camera& c = model.cameras[std::size_t(node.camera)];
      if (c.type == "perspective") camera = toCamera(c, node.camera, world, reader, where);
    }
    if (auto light = node.extensions.find("KHR_lights_punctual");
        light != node.extensions.end() && light->second.Has("light")) {
      const int lightIndex = light->second.Get("light").GetNumberAsInt();
      if (lightIndex < 0 || std::size_t(lightIndex) >= model.lights.size())
        reader.fail(where, "KHR_lights_punctual light index out of range");
      scene.lights.push_back(toLight(model.lights[std::size_t(lightIndex)], lightIndex, world, reader, where));
    }
    for (int child : node.children) stack.push_back({child, world});
  }
  if (scene.objects.empty()) throw InputError(source, 0, "no meshes", "the glTF scene has no node with a mesh");
  scene.camera = camera ? *camera : frameBounds(cageBounds(scene));
  if (scene.lights.empty()) addDefaultLighting(scene);
  return scene;
}

}  // namespace facet::scene
