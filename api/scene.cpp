// Scenes from files through the engine's loaders, and from code through the
// same rules the JSON loader applies, each error naming the field.
#include <glm/geometric.hpp>

#include <cmath>
#include <string>

#include "api/errors.h"
#include "api/material.h"
#include "api/scene_data.h"
#include "scenes/input_error.h"
#include "scenes/camera_rules.h"
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

glm::dvec3 color(const Vec3& v, const std::string& field) {
  const glm::dvec3 c = finite(v, field);
  if (const auto rule = scene::radianceRule(c)) fail(field, *rule);
  return c;
}

glm::dvec3 direction(const Vec3& v, const std::string& field) {
  const glm::dvec3 d = finite(v, field);
  if (glm::length(d) < 1e-12) fail(field, "a direction must not be the zero vector");
  return glm::normalize(d);
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

scene::Light engineLight(const Light& light, const std::string& where) {
  scene::Light out;
  out.type = light.type == LightType::Point  ? scene::LightType::Point
             : light.type == LightType::Spot ? scene::LightType::Spot
                                             : scene::LightType::Directional;
  out.color = color(light.color, where + ".color");
  out.position = finite(light.position, where + ".position");
  out.direction = direction(light.direction, where + ".direction");
  out.outerConeDegrees = inRange(light.outerConeDegrees, 0, scene::kMaxSpotConeDegrees, where + ".outerConeDegrees");
  out.innerConeDegrees = inRange(light.innerConeDegrees, 0, out.outerConeDegrees, where + ".innerConeDegrees");
  return out;
}

scene::Camera engineCamera(const Camera& camera) {
  scene::Camera out;
  out.eye = finite(camera.eye, "camera.eye");
  out.target = finite(camera.target, "camera.target");
  out.up = direction(camera.up, "camera.up");
  out.verticalFovDegrees =
      inRange(camera.verticalFovDegrees, scene::kMinFovDegrees, scene::kMaxFovDegrees, "camera.verticalFovDegrees");
  if (const char* problem = scene::cameraProblem(out)) fail("camera", problem);
  return out;
}

scene::Environment engineEnvironment(const Environment& environment) {
  scene::Environment out;
  try {
    out.map = std::make_shared<const scene::EnvironmentMap>(scene::loadEnvironmentMap(environment.file));
  } catch (const scene::InputError& e) {
    fail("environment.file", e.what());
  }
  out.intensity = inRange(environment.intensity, 0, HUGE_VAL, "environment.intensity");
  if (const auto rule = scene::radianceRule(glm::dvec3(out.intensity * out.map->largestRadiance())))
    fail("environment.intensity", "the brightest texel times the intensity " + *rule);
  out.rotationDegrees = inRange(environment.rotationDegrees, -HUGE_VAL, HUGE_VAL, "environment.rotationDegrees");
  out.method = environment.method == IblMethod::Sampled ? scene::IblMethod::Sampled : scene::IblMethod::Prefiltered;
  out.samples = int(inRange(environment.samples, 1, 16384, "environment.samples"));
  out.occlusion = environment.occlusion;
  return out;
}

scene::Scene engineScene(const SceneDescription& d) {
  scene::Scene s;
  s.source = kSource;
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
  s.camera = d.camera ? engineCamera(*d.camera) : scene::frameBounds(scene::cageBounds(s));
  for (std::size_t i = 0; i < d.lights.size(); ++i)
    s.lights.push_back(engineLight(d.lights[i], "lights[" + std::to_string(i) + "]"));
  if (d.environment) s.environment = engineEnvironment(*d.environment);
  if (s.lights.empty()) scene::addDefaultLighting(s);
  s.render.width = int(inRange(d.width, 1, 16384, "width"));
  s.render.height = int(inRange(d.height, 1, 16384, "height"));
  return s;
}

Scene wrap(scene::Scene s) { return Scene(std::make_shared<const detail::SceneData>(detail::SceneData{std::move(s)})); }

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
  return api::translateErrors([&] { return wrap(engineScene(description)); });
}

}  // namespace facet::v0
