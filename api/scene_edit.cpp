// Changing a Scene: each value is written as the scene file's JSON block of
// the same name and read by the scene file's own readers, so that an edit
// obeys exactly the file's rules and its errors read as the file's do.
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <utility>

#include "api/errors.h"
#include "api/material.h"
#include "api/scene_data.h"
#include "scenes/input_error.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"

namespace facet::v0 {
namespace {

using nlohmann::json;

constexpr const char* kSource = "scene";  // what errors name for a change made in code

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
Vec3 vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// `data` with `change` applied to a copy: copies of the Scene made before keep what they had.
template <class Change>
std::shared_ptr<const detail::SceneData> changed(const detail::SceneData& data, Change&& change) {
  auto copy = std::make_shared<detail::SceneData>(data);
  change(copy->scene);
  return copy;
}

const scene::Object& objectAt(const scene::Scene& s, int object) {
  if (object < 0 || std::size_t(object) >= s.objects.size())
    throw scene::InputError(kSource, 0, "objects[" + std::to_string(object) + "]",
                            "no such object (the scene has " + std::to_string(s.objects.size()) + ")");
  return s.objects[std::size_t(object)];
}

// The object's material becomes `material`: in its place when no other
// object shares it, so that the scene's materials stay as a file that names
// this material would have them.
void replaceMaterial(scene::Scene& s, int object, materials::Material material) {
  scene::Object& target = s.objects[std::size_t(object)];
  int users = 0;
  for (const scene::Object& o : s.objects) users += o.material == target.material;
  if (users == 1) {
    s.materials[std::size_t(target.material)] = std::move(material);
    return;
  }
  target.material = int(s.materials.size());
  s.materials.push_back(std::move(material));
}

json cameraBlock(const Camera& c) {
  return {{"eye", vec(c.eye)}, {"target", vec(c.target)}, {"up", vec(c.up)}, {"fov", c.verticalFovDegrees}};
}

json lightBlock(const Light& l) {
  json block = {{"type", l.type == LightType::Point  ? "point"
                         : l.type == LightType::Spot ? "spot"
                                                     : "directional"},
                {"color", vec(l.color)}};
  if (l.type != LightType::Directional) block["position"] = vec(l.position);
  if (l.type != LightType::Point) block["direction"] = vec(l.direction);
  if (l.type == LightType::Spot) block["inner_cone"] = l.innerConeDegrees, block["outer_cone"] = l.outerConeDegrees;
  return block;
}

const char* methodName(IblMethod method) {
  return method == IblMethod::Sampled ? "sampled" : method == IblMethod::Filtered ? "filtered" : "prefiltered";
}

// The file is named only when it is not the map the scene holds, which the
// block then keeps.
json environmentBlock(const Environment& e, const std::optional<scene::Environment>& current) {
  json block = {{"intensity", e.intensity}, {"rotation", e.rotationDegrees}};
  if (e.samples) block["samples"] = *e.samples;
  if (e.method) {
    block["method"] = methodName(*e.method);
    block["occlusion"] = e.occlusion;
  }
  if (!current || current->map->source.string() != e.file) block["file"] = e.file;
  return block;
}

}  // namespace

std::vector<std::string> Scene::warnings() const { return data_->scene.warnings; }

std::string Scene::objectName(int object) const {
  return api::translateErrors([&] { return objectAt(data_->scene, object).name; });
}

std::string Scene::materialName(int object) const {
  return api::translateErrors(
      [&] { return data_->scene.materials[std::size_t(objectAt(data_->scene, object).material)].name; });
}

void Scene::setMaterial(int object, const Material& material) {
  data_ = api::translateErrors([&] {
    objectAt(data_->scene, object);
    materials::Material m = api::toEngineMaterial(material, "objects[" + std::to_string(object) + "].material");
    return changed(*data_, [&](scene::Scene& s) { replaceMaterial(s, object, std::move(m)); });
  });
}

void Scene::setMaterial(int object, const std::string& reference) {
  data_ = api::translateErrors([&] {
    objectAt(data_->scene, object);
    std::vector<scene::Texture> textures = data_->scene.textures;
    materials::Material m = scene::readObjectMaterial(json(reference), object, kSource, textures);
    m.name = std::filesystem::path(reference).stem().string();
    return changed(*data_, [&](scene::Scene& s) {
      s.textures = std::move(textures);
      replaceMaterial(s, object, std::move(m));
    });
  });
}

Camera Scene::camera() const {
  const scene::Camera& c = data_->scene.camera;
  return {vec(c.eye), vec(c.target), vec(c.up), c.verticalFovDegrees};
}

void Scene::setCamera(const Camera& camera) {
  data_ = api::translateErrors([&] {
    const scene::Camera c = scene::readCameraBlock(cameraBlock(camera), kSource);
    return changed(*data_, [&](scene::Scene& s) { s.camera = c; });
  });
}

std::optional<Environment> Scene::environment() const {
  const std::optional<scene::Environment>& e = data_->scene.environment;
  if (!e) return std::nullopt;
  const IblMethod method = e->method == scene::IblMethod::Sampled    ? IblMethod::Sampled
                           : e->method == scene::IblMethod::Filtered ? IblMethod::Filtered
                                                                     : IblMethod::Prefiltered;
  return Environment{e->map->source.string(),
                     e->intensity,
                     e->rotationDegrees,
                     e->methodStated ? std::optional(method) : std::nullopt,
                     e->samplesStated ? std::optional(e->samples) : std::nullopt,
                     e->occlusion};
}

void Scene::setEnvironment(const std::optional<Environment>& environment) {
  data_ = api::translateErrors([&] {
    std::optional<scene::Environment> e;
    if (environment)
      e = scene::readEnvironmentBlock(environmentBlock(*environment, data_->scene.environment), kSource,
                                      data_->scene.environment);
    if (scene::bouncesContradictEnvironment(data_->scene.render, e))
      throw scene::InputError(kSource, 0, "render.bounces", scene::kBouncesNeedOcclusionRule);
    return changed(*data_, [&](scene::Scene& s) { s.environment = std::move(e); });
  });
}

std::vector<Light> Scene::lights() const {
  std::vector<Light> out;
  for (const scene::Light& l : data_->scene.lights) {
    const LightType type = l.type == scene::LightType::Point  ? LightType::Point
                           : l.type == scene::LightType::Spot ? LightType::Spot
                                                              : LightType::Directional;
    out.push_back({type, vec(l.color), vec(l.position), vec(l.direction), l.innerConeDegrees, l.outerConeDegrees});
  }
  return out;
}

void Scene::setLights(const std::vector<Light>& lights) {
  data_ = api::translateErrors([&] {
    json blocks = json::array();
    for (const Light& l : lights) blocks.push_back(lightBlock(l));
    std::vector<scene::Light> ls = scene::readLightsBlock(blocks, kSource);
    return changed(*data_, [&](scene::Scene& s) { s.lights = std::move(ls); });
  });
}

Cage loadCage(const std::string& path) {
  return api::translateErrors([&] {
    const scene::ControlCage c = scene::loadObjCage(path);
    // What a Cage cannot hold would be lost silently: such a cage is loaded as a scene.
    const scene::SubdivisionOptions plain;
    const bool tagged = c.options.boundary != plain.boundary || c.options.faceVarying != plain.faceVarying ||
                        c.options.creasing != plain.creasing || c.options.triangles != plain.triangles;
    const char* lost = !c.texcoords.empty() ? "texture coordinates"
                       : !c.corners.empty() ? "corner sharpness"
                       : !c.holes.empty()   ? "holes"
                       : tagged             ? "subdivision options"
                                            : nullptr;
    if (lost)
      throw scene::InputError(path, 0, lost,
                              "a Cage holds positions, faces and creases only; load the file with loadScene");
    Cage cage;
    for (const glm::dvec3& p : c.positions) cage.positions.push_back(vec(p));
    cage.faceVertexCounts = c.faceVertexCounts;
    cage.faceVertexIndices = c.faceVertexIndices;
    for (const scene::CreaseEdge& e : c.creases) cage.creases.push_back({e.v0, e.v1, e.sharpness});
    return cage;
  });
}

}  // namespace facet::v0
