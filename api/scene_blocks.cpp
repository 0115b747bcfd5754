#include "api/scene_blocks.h"

#include "api/scene_data.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"

namespace facet::api {
namespace {

using nlohmann::json;
using v0::Vec3;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
Vec3 vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

const char* methodName(v0::IblMethod method) {
  return method == v0::IblMethod::Sampled ? "sampled" : method == v0::IblMethod::Filtered ? "filtered" : "prefiltered";
}

}  // namespace

json cameraBlock(const v0::Camera& c) {
  return {{"eye", vec(c.eye)}, {"target", vec(c.target)}, {"up", vec(c.up)}, {"fov", c.fov}};
}

json lightsBlock(const std::vector<v0::Light>& lights) {
  json blocks = json::array();
  for (const v0::Light& l : lights) {
    json block = {{"type", l.type == v0::LightType::Point  ? "point"
                           : l.type == v0::LightType::Spot ? "spot"
                                                           : "directional"},
                  {"color", vec(l.color)}};
    if (l.type != v0::LightType::Directional) block["position"] = vec(l.position);
    if (l.type != v0::LightType::Point) block["direction"] = vec(l.direction);
    if (l.type == v0::LightType::Spot) block["inner_cone"] = l.innerCone, block["outer_cone"] = l.outerCone;
    blocks.push_back(std::move(block));
  }
  return blocks;
}

json environmentBlock(const v0::Environment& e, const std::optional<scene::Environment>& current) {
  json block = {{"intensity", e.intensity}, {"rotation", e.rotation}};
  if (e.samples) block["samples"] = *e.samples;
  if (e.method) {
    block["method"] = methodName(*e.method);
    block["occlusion"] = e.occlusion;
  }
  if (!current || current->map->source.string() != e.file) block["file"] = e.file;
  return block;
}

json transformBlock(const v0::Transform& t) {
  return {{"translate", vec(t.translate)}, {"rotate", vec(t.rotate)}, {"scale", vec(t.scale)}};
}

v0::Camera apiCamera(const scene::Camera& c) { return {vec(c.eye), vec(c.target), vec(c.up), c.verticalFovDegrees}; }

std::vector<v0::Light> apiLights(const std::vector<scene::Light>& lights) {
  std::vector<v0::Light> out;
  for (const scene::Light& l : lights) {
    const v0::LightType type = l.type == scene::LightType::Point  ? v0::LightType::Point
                               : l.type == scene::LightType::Spot ? v0::LightType::Spot
                                                                  : v0::LightType::Directional;
    out.push_back({type, vec(l.color), vec(l.position), vec(l.direction), l.innerConeDegrees, l.outerConeDegrees});
  }
  return out;
}

std::optional<v0::Environment> apiEnvironment(const std::optional<scene::Environment>& e) {
  if (!e) return std::nullopt;
  const v0::IblMethod method = e->method == scene::IblMethod::Sampled    ? v0::IblMethod::Sampled
                               : e->method == scene::IblMethod::Filtered ? v0::IblMethod::Filtered
                                                                         : v0::IblMethod::Prefiltered;
  return v0::Environment{e->map->source.string(),
                         e->intensity,
                         e->rotationDegrees,
                         e->methodStated ? std::optional(method) : std::nullopt,
                         e->samplesStated ? std::optional(e->samples) : std::nullopt,
                         e->occlusion};
}

glm::dmat4 transformMatrix(const json& transform, const std::string& field) {
  return scene::readTransformBlock(transform, field, api::kCodeSource);
}

v0::Transform apiTransform(const json& block, const std::string& field) {
  transformMatrix(block, field);
  if (block.contains("matrix"))
    throw scene::InputError(api::kCodeSource, 0, field,
                            "is a matrix in the scene file, which a Transform (translate, rotate, scale) cannot "
                            "hold; set one to replace it");
  auto vec = [](const json& v) { return Vec3{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; };
  v0::Transform t;
  if (block.contains("translate")) t.translate = vec(block["translate"]);
  if (block.contains("rotate")) t.rotate = vec(block["rotate"]);
  if (block.contains("scale"))
    t.scale = block["scale"].is_array() ? vec(block["scale"]) : Vec3{block["scale"], block["scale"], block["scale"]};
  return t;
}

}  // namespace facet::api
