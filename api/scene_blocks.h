// The API's scene values written as the scene file's JSON blocks of the same
// name, so that the file's own readers validate every edit.
#pragma once

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "facet/scene.h"
#include "scenes/scene.h"

namespace facet::api {

nlohmann::json cameraBlock(const v0::Camera& camera);
nlohmann::json lightsBlock(const std::vector<v0::Light>& lights);
// The file is named only when it is not the map `current` holds, which the
// block then keeps.
nlohmann::json environmentBlock(const v0::Environment& environment, const std::optional<scene::Environment>& current);
nlohmann::json transformBlock(const v0::Transform& transform);

v0::Camera apiCamera(const scene::Camera& camera);
std::vector<v0::Light> apiLights(const std::vector<scene::Light>& lights);
std::optional<v0::Environment> apiEnvironment(const std::optional<scene::Environment>& environment);

// A transform block read by the file's rules, errors naming `field`.
glm::dmat4 transformMatrix(const nlohmann::json& transform, const std::string& field);
// A transform block as a Transform; one written as a matrix has none.
v0::Transform apiTransform(const nlohmann::json& transform, const std::string& field);

}  // namespace facet::api
