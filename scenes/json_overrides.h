// `--set PATH=VALUE`: one field of a scene's JSON replaced before the scene
// is validated, so an override obeys exactly the rules the file does
// (docs/scene-format.md, "The command line: --material and --set").
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace facet::scene {

struct JsonOverride {
  std::string path;   // render.spp, materials.gold.roughness, objects[0].material
  std::string value;  // JSON where it parses as JSON (16, true, [0, 1, 2]), else a string (silver)

  // "PATH=VALUE", as error messages quote it.
  std::string text() const { return path + "=" + value; }
};

// "PATH=VALUE" split at its first '='; throws std::invalid_argument
// "--set '<text>': ..." when there is no '=' or the path is malformed.
JsonOverride parseJsonOverride(const std::string& assignment);

// Sets the field `o.path` names in `document`, making the objects on the way
// where they are missing; an array index must name an existing element.
// Throws std::invalid_argument "--set PATH=VALUE: <what is in the way>".
void applyJsonOverride(nlohmann::json& document, const JsonOverride& o);

// Whether a problem reported at `field` (a path as the scene reader names
// fields) lies on the override's path: the field itself, inside the value
// it set, or an object that holds it.
bool overrideConcerns(const JsonOverride& o, const std::string& field);

}  // namespace facet::scene
