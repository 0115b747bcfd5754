// glTF nodes: the hierarchy, its transforms, and the cameras and
// KHR_lights_punctual lights its nodes place.
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "scenes/gltf_internal.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {

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

Light toLight(const tinygltf::Light& gltf, int index, const glm::dmat4& world, const GltfReader& reader,
              const std::string& where) {
  const std::string field = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
  Light light;
  glm::dvec3 color(1.0);
  if (gltf.color.size() == 3) color = {gltf.color[0], gltf.color[1], gltf.color[2]};
  if (hasNegativeComponent(color)) reader.fail(field + ".color", kNegativeColorRule);
  if (gltf.intensity < 0) reader.fail(where, "light intensity must not be negative");
  light.color = color * gltf.intensity / std::numbers::pi;
  if (const auto rule = radianceRule(light.color)) reader.fail(field, "color times intensity / pi " + *rule);
  light.position = glm::dvec3(world[3]);
  if (gltf.range > 0.0)
    reader.warn(field + ".range", "is not read; the light falls off as 1/d^2 at any distance, as without a range");
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

}  // namespace facet::scene::detail
