// Changing a Scene: each value is written as the scene file's JSON block of
// the same name and read by the scene file's own readers, so that an edit
// obeys exactly the file's rules and its errors read as the file's do.
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <utility>

#include "api/errors.h"
#include "api/material.h"
#include "api/scene_blocks.h"
#include "api/scene_data.h"
#include "api/scene_objects.h"
#include "scenes/input_error.h"
#include "scenes/obj_cage.h"
#include "scenes/placement.h"
#include "scenes/scene_file.h"

namespace facet::v0 {
namespace {

using nlohmann::json;

Vec3 vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

const scene::Object& objectAt(const scene::Scene& s, int object) {
  if (object < 0 || std::size_t(object) >= s.objects.size())
    throw scene::InputError(api::kCodeSource, 0, "objects[" + std::to_string(object) + "]",
                            "no such object (the scene has " + std::to_string(s.objects.size()) + ")");
  return s.objects[std::size_t(object)];
}

}  // namespace
}  // namespace facet::v0

namespace facet::api {

void wearMaterial(scene::Scene& s, int object, materials::Material material) {
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

void placeObject(v0::detail::SceneData& data, int object, const nlohmann::json& transform) {
  const std::string field = "objects[" + std::to_string(object) + "].transform";
  // The cage holds the authored one placed by the old transform: undone, then placed by the new.
  const glm::dmat4 old = transformMatrix(data.transforms[std::size_t(object)], field);
  const glm::dmat4 change = transformMatrix(transform, field) * glm::inverse(old);
  scene::transformCage(data.scene.objects[std::size_t(object)].cage, change);
  data.transforms[std::size_t(object)] = transform;
}

}  // namespace facet::api

namespace facet::v0 {

std::vector<std::string> Scene::warnings() const { return data_->scene.warnings; }

std::string Scene::objectName(int object) const {
  return api::translateErrors([&] { return objectAt(data_->scene, object).name; });
}

std::string Scene::materialName(int object) const {
  return api::translateErrors(
      [&] { return data_->scene.materials[std::size_t(objectAt(data_->scene, object).material)].name; });
}

std::vector<std::string> Scene::materialNames() const {
  std::vector<std::string> names;
  for (const materials::Material& m : data_->scene.materials) names.push_back(m.name);
  return names;
}

void Scene::setMaterial(int object, const Material& material) {
  data_ = api::translateErrors([&] {
    objectAt(data_->scene, object);
    materials::Material m = api::toEngineMaterial(material, "objects[" + std::to_string(object) + "].material");
    return api::changed(*data_, [&](detail::SceneData& d) { api::wearMaterial(d.scene, object, std::move(m)); });
  });
}

void Scene::setMaterial(int object, const std::string& reference) {
  data_ = api::translateErrors([&] {
    return api::readingInputs([&] {
      objectAt(data_->scene, object);
      std::vector<scene::Texture> textures = data_->scene.textures;
      materials::Material m = scene::readObjectMaterial(json(reference), object, api::kCodeSource,
                                                        std::filesystem::current_path() / "", textures);
      m.name = std::filesystem::path(reference).stem().string();
      return api::changed(*data_, [&](detail::SceneData& d) {
        d.scene.textures = std::move(textures);
        api::wearMaterial(d.scene, object, std::move(m));
      });
    });
  });
}

int Scene::addObject(const Object& object) {
  const int index = objectCount();
  data_ = api::translateErrors([&] {
    scene::Object o = api::engineObject(object, index, int(data_->scene.materials.size()));
    return api::changed(*data_, [&](detail::SceneData& d) {
      d.scene.objects.push_back(std::move(o));
      d.transforms.push_back(api::transformBlock(object.transform));
    });
  });
  return index;
}

void Scene::removeObject(int object) {
  data_ = api::translateErrors([&] {
    objectAt(data_->scene, object);
    if (data_->scene.objects.size() == 1)
      throw scene::InputError(api::kCodeSource, 0, "objects[" + std::to_string(object) + "]",
                              "is the scene's last object, and a scene needs at least one");
    return api::changed(*data_, [&](detail::SceneData& d) {
      d.scene.objects.erase(d.scene.objects.begin() + object);
      d.transforms.erase(d.transforms.begin() + object);
    });
  });
}

void Scene::moveObject(int object, int to) {
  data_ = api::translateErrors([&] {
    objectAt(data_->scene, object);
    objectAt(data_->scene, to);
    return api::changed(*data_, [&](detail::SceneData& d) {
      auto move = [&](auto& items) {
        auto moved = std::move(items[std::size_t(object)]);
        items.erase(items.begin() + object);
        items.insert(items.begin() + to, std::move(moved));
      };
      move(d.scene.objects);
      move(d.transforms);
    });
  });
}

Transform Scene::transform(int object) const {
  return api::translateErrors([&] {
    objectAt(data_->scene, object);
    return api::apiTransform(data_->transforms[std::size_t(object)],
                             "objects[" + std::to_string(object) + "].transform");
  });
}

void Scene::setTransform(int object, const Transform& transform) {
  data_ = api::translateErrors([&] {
    objectAt(data_->scene, object);
    return api::changed(*data_,
                        [&](detail::SceneData& d) { api::placeObject(d, object, api::transformBlock(transform)); });
  });
}

Camera Scene::camera() const { return api::apiCamera(data_->scene.camera); }

void Scene::setCamera(const Camera& camera) {
  data_ = api::translateErrors([&] {
    const scene::Camera c = scene::readCameraBlock(api::cameraBlock(camera), api::kCodeSource);
    return api::changed(*data_, [&](detail::SceneData& d) { d.scene.camera = c; });
  });
}

std::optional<Environment> Scene::environment() const { return api::apiEnvironment(data_->scene.environment); }

void Scene::setEnvironment(const std::optional<Environment>& environment) {
  data_ = api::translateErrors([&] {
    return api::readingInputs([&] {
      std::optional<scene::Environment> e;
      if (environment)
        e = scene::readEnvironmentBlock(api::environmentBlock(*environment, data_->scene.environment), api::kCodeSource,
                                        std::filesystem::current_path() / "", data_->scene.environment);
      if (scene::bouncesContradictEnvironment(data_->scene.render, e))
        throw scene::InputError(api::kCodeSource, 0, "render.bounces", scene::kBouncesNeedOcclusionRule);
      return api::changed(*data_, [&](detail::SceneData& d) { d.scene.environment = std::move(e); });
    });
  });
}

std::vector<Light> Scene::lights() const { return api::apiLights(data_->scene.lights); }

void Scene::setLights(const std::vector<Light>& lights) {
  data_ = api::translateErrors([&] {
    std::vector<scene::Light> ls = scene::readLightsBlock(api::lightsBlock(lights), api::kCodeSource);
    return api::changed(*data_, [&](detail::SceneData& d) { d.scene.lights = std::move(ls); });
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
