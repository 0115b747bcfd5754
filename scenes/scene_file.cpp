#include "scenes/scene_file.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "scenes/input_error.h"
#include "scenes/input_file.h"
#include "scenes/obj_cage.h"
#include "scenes/studio_environment.h"

namespace facet::scene {

Scene loadScene(const std::filesystem::path& path, std::span<const JsonOverride> overrides,
                const std::string& variant) {
  checkInputFile(path, "the scene");
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (!variant.empty() && extension != ".gltf" && extension != ".glb")
    throw InputError(path.string(), 0, "a material variant is one of a glTF file's (KHR_materials_variants)",
                     "variant '" + variant + "' is named, and this is no glTF file");
  if (extension == ".json") return loadJsonScene(path, overrides);
  const bool cage = extension == ".obj", gltf = extension == ".gltf" || extension == ".glb";
  if (cage || gltf) {
    Scene scene = cage ? sceneFromCage(loadObjCage(path)) : loadGltfScene(path, variant);
    scene.render.bouncesStated = false;  // a model file says nothing of light transport or sampling
    scene.render.sampling = Sampling::Chosen;
    applyModelOverrides(scene, path, overrides);
    return scene;
  }
  throw InputError(path.string(), 0, "unknown scene format",
                   "expected a .json scene, an .obj control cage, or a .gltf / .glb file");
}

Scene sceneFromCage(ControlCage cage) {
  Scene scene;
  scene.source = cage.source;
  scene.materials.push_back(defaultMaterial());
  Object object;
  object.name = std::filesystem::path(cage.source).stem().string();
  object.cage = std::move(cage);
  scene.objects.push_back(std::move(object));
  scene.camera = frameBounds(cageBounds(scene));
  addDefaultLighting(scene);
  return scene;
}

void assignMaterial(Scene& scene, const std::string& objectName, materials::Material material) {
  const int index = int(scene.materials.size());
  bool found = false;
  for (Object& object : scene.objects)
    if (objectName.empty() || object.name == objectName) object.material = index, found = true;
  if (!found) {
    std::set<std::string> names;
    for (const Object& object : scene.objects) names.insert(object.name);
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "'" : ", '") + name + "'";
    throw std::invalid_argument("no object is called '" + objectName + "' (the objects: " + list + ")");
  }
  scene.materials.push_back(std::move(material));
}

std::optional<Subdivision> subdivisionNamed(std::string_view name) {
  if (name == "catmull-clark") return Subdivision::CatmullClark;
  if (name == "none") return Subdivision::None;
  return std::nullopt;
}

void overrideSubdivision(Scene& scene, const std::string& name, const std::string& option) {
  const std::optional<Subdivision> subdivision = subdivisionNamed(name);
  if (!subdivision)
    throw std::invalid_argument(option + " '" + name + "': expected one of: " + std::string(kSubdivisionNames));
  for (Object& object : scene.objects) object.subdivision = *subdivision;
}

materials::Material defaultMaterial() {
  materials::Material m;
  m.name = "default";
  m.distribution = rules::f64::D_GGX;
  m.geometry = rules::f64::G_SMITH_GGX_CORRELATED;
  m.fresnel = rules::f64::F_SCHLICK;
  m.alpha = 0.25;
  m.f0 = glm::dvec3(0.04);
  m.diffuse = glm::dvec3(0.5);
  return m;
}

Camera frameBounds(const Aabb& bounds, double verticalFovDegrees) {
  Camera camera;
  camera.verticalFovDegrees = verticalFovDegrees;
  camera.target = bounds.centre();
  const double radius = std::max(0.5 * bounds.diagonal(), 1e-6);
  const double halfFov = 0.5 * verticalFovDegrees * std::numbers::pi / 180.0;
  const double distance = radius / (0.9 * std::sin(halfFov));
  camera.eye = camera.target + distance * glm::normalize(glm::dvec3(1.0, 0.75, 1.5));
  camera.up = {0.0, 1.0, 0.0};
  return camera;
}

Light defaultKeyLight(const Camera& camera) {
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::dvec3 up = glm::cross(right, forward);
  Light light;
  light.type = LightType::Directional;
  light.color = glm::dvec3(1.0);
  light.direction = glm::normalize(forward + 0.6 * right - 1.0 * up);
  return light;
}

void addDefaultLighting(Scene& scene) {
  if (!scene.environment) scene.environment = studioEnvironment();
}

Aabb cageBounds(const Scene& scene) {
  Aabb bounds;
  for (const Object& object : scene.objects)
    for (const glm::dvec3& p : object.cage.positions) bounds.extend(p);
  return bounds;
}

}  // namespace facet::scene
