// The objects a Scene is given in code, validated by the rules the scene
// file's readers apply, each error naming the field.
#include "api/scene_objects.h"

#include <cmath>
#include <string>

#include "api/scene_blocks.h"
#include "api/scene_data.h"
#include "scenes/input_error.h"
#include "scenes/placement.h"
#include "scenes/value_rules.h"

namespace facet::api {
namespace {

using v0::Cage;
using v0::Crease;
using v0::Vec3;

[[noreturn]] void fail(const std::string& field, const std::string& rule) {
  throw scene::InputError(api::kCodeSource, 0, field, rule);
}

glm::dvec3 finite(const Vec3& v, const std::string& field) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) fail(field, "must be finite");
  return {v.x, v.y, v.z};
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
                           float(checkedRange(c.sharpness, 0, HUGE_VAL, field + ".sharpness"))});
  }
  return out;
}

}  // namespace

double checkedRange(double x, double lo, double hi, const std::string& field) {
  if (!std::isfinite(x)) fail(field, "must be finite");
  if (const std::optional<std::string> rule = scene::rangeRule(x, lo, hi)) fail(field, *rule);
  return x;
}

scene::Object engineObject(const v0::Object& o, int index, int materialCount) {
  const std::string where = "objects[" + std::to_string(index) + "]";
  scene::Object object;
  object.name = o.name.empty() ? where : o.name;
  object.cage = engineCage(o.cage, where + ".cage");
  scene::transformCage(object.cage, transformMatrix(transformBlock(o.transform), where + ".transform"));
  object.material = int(checkedRange(o.material, 0, double(materialCount - 1), where + ".material"));
  object.subdivision = o.subdivided ? scene::Subdivision::CatmullClark : scene::Subdivision::None;
  return object;
}

v0::Scene sceneOf(scene::Scene s, std::filesystem::path relativeTo, const nlohmann::json& document,
                  std::vector<std::filesystem::path> inputs) {
  std::map<std::string, nlohmann::json> namedMaterials;
  std::vector<nlohmann::json> transforms(s.objects.size(), nlohmann::json::object());
  if (document.is_object()) {
    if (const auto block = document.find("materials"); block != document.end() && block->is_object())
      for (const auto& [name, material] : block->items()) namedMaterials[name] = material;
    // The loader read every object, so objects is an array of one per object.
    const nlohmann::json& objects = document.at("objects");
    for (std::size_t i = 0; i < transforms.size(); ++i)
      transforms[i] = objects.at(i).value("transform", nlohmann::json::object());
  }
  return v0::Scene(std::make_shared<const v0::detail::SceneData>(v0::detail::SceneData{
      std::move(s), std::move(relativeTo), std::move(namedMaterials), std::move(inputs), std::move(transforms)}));
}

}  // namespace facet::api
