// Scenes from files through the engine's loaders, and from code through the
// same rules the JSON loader applies (its own readers for the camera, lights
// and environment), each error naming the field.
#include <cmath>
#include <string>

#include "api/errors.h"
#include "api/material.h"
#include "api/scene_data.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/value_rules.h"

namespace facet::v0 {
namespace {

constexpr const char* kSource = "scene";  // what errors name for a scene built in code

[[noreturn]] void fail(const std::string& field, const std::string& rule) {
  throw scene::InputError(kSource, 0, field, rule);
}

glm::dvec3 finite(const Vec3& v, const std::string& field) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) fail(field, "must be finite");
  return {v.x, v.y, v.z};
}

double inRange(double x, double lo, double hi, const std::string& field) {
  if (!std::isfinite(x)) fail(field, "must be finite");
  if (const std::optional<std::string> rule = scene::rangeRule(x, lo, hi)) fail(field, *rule);
  return x;
}

scene::ControlCage engineCage(const Cage& cage, const std::string& where) {
  scene::ControlCage out;
  out.source = where;
  for (std::size_t i = 0; i < cage.positions.size(); ++i)
    out.positions.push_back(finite(cage.positions[i], where + ".positions[" + std::to_string(i) + "]"));
  std::size_t corners = 0;
  for (std::size_t f = 0; f < cage.faceVertexCounts.size(); ++f) {
    if (cage.faceVertexCounts[f] < 3)
      fail(where + ".faceVertexCounts[" + std::to_string(f) + "]", "a face needs at least 3 vertices");
    corners += std::size_t(cage.faceVertexCounts[f]);
  }
  if (cage.faceVertexCounts.empty()) fail(where + ".faceVertexCounts", "a cage needs at least one face");
  if (corners != cage.faceVertexIndices.size())
    fail(where + ".faceVertexIndices",
         "must hold " + std::to_string(corners) + " indices (the sum of faceVertexCounts)");
  auto vertex = [&](int index, const std::string& field) {
    if (index < 0 || index >= out.vertexCount())
      fail(field, "vertex " + std::to_string(index) + " is out of range (the cage has " +
                      std::to_string(out.vertexCount()) + ")");
    return index;
  };
  for (std::size_t i = 0; i < cage.faceVertexIndices.size(); ++i)
    out.faceVertexIndices.push_back(
        vertex(cage.faceVertexIndices[i], where + ".faceVertexIndices[" + std::to_string(i) + "]"));
  out.faceVertexCounts = cage.faceVertexCounts;
  for (std::size_t i = 0; i < cage.creases.size(); ++i) {
    const std::string field = where + ".creases[" + std::to_string(i) + "]";
    const Crease& c = cage.creases[i];
    out.creases.push_back({vertex(c.v0, field + ".v0"), vertex(c.v1, field + ".v1"),
                           float(inRange(c.sharpness, 0, HUGE_VAL, field + ".sharpness"))});
  }
  return out;
}

scene::Scene engineScene(const SceneDescription& d) {
  scene::Scene s;
  s.source = kSource;
  s.render.bouncesStated = false;  // RenderSettings::bounces and samplesPerPixel state them
  s.render.sampling = scene::Sampling::Chosen;
  for (std::size_t i = 0; i < d.materials.size(); ++i)
    s.materials.push_back(api::toEngineMaterial(d.materials[i], "materials[" + std::to_string(i) + "]"));
  if (s.materials.empty()) s.materials.push_back(scene::defaultMaterial());
  if (d.objects.empty()) fail("objects", "a scene needs at least one object");
  for (std::size_t i = 0; i < d.objects.size(); ++i) {
    const Object& o = d.objects[i];
    const std::string where = "objects[" + std::to_string(i) + "]";
    scene::Object object;
    object.name = o.name.empty() ? where : o.name;
    object.cage = engineCage(o.cage, where + ".cage");
    object.material = int(inRange(o.material, 0, double(s.materials.size() - 1), where + ".material"));
    object.subdivision = o.subdivided ? scene::Subdivision::CatmullClark : scene::Subdivision::None;
    s.objects.push_back(std::move(object));
  }
  s.camera = scene::frameBounds(scene::cageBounds(s));
  s.render.width = int(inRange(d.width, 1, 16384, "width"));
  s.render.height = int(inRange(d.height, 1, 16384, "height"));
  return s;
}

Scene wrap(scene::Scene s) { return Scene(std::make_shared<const detail::SceneData>(detail::SceneData{std::move(s)})); }

// Camera, lights and environment go through the scene's own setters, which
// read them as a scene file's blocks.
Scene described(const SceneDescription& d) {
  Scene scene = wrap(engineScene(d));
  if (d.camera) scene.setCamera(*d.camera);
  scene.setLights(d.lights);
  scene.setEnvironment(d.environment);
  if (d.lights.empty()) {
    scene::Scene s = scene.data().scene;
    scene::addDefaultLighting(s);
    scene = wrap(std::move(s));
  }
  return scene;
}

}  // namespace

Scene::Scene(std::shared_ptr<const detail::SceneData> data) : data_(std::move(data)) {
  if (!data_) throw Error(ErrorKind::BadInput, "Scene: no scene data; make a Scene with loadScene or buildScene");
}

int Scene::width() const { return data_->scene.render.width; }
int Scene::height() const { return data_->scene.render.height; }
int Scene::objectCount() const { return int(data_->scene.objects.size()); }

Scene loadScene(const std::string& path) {
  return api::translateErrors([&] { return wrap(scene::loadScene(path)); });
}

Scene buildScene(const SceneDescription& description) {
  return api::translateErrors([&] { return described(description); });
}

}  // namespace facet::v0
