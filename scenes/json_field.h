// The JSON scene reader's view of a value with the path that names it, and
// the readers of its "render" and "environment" objects
// (scene_json_settings.cpp); internal to scenes/.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "materials/strict_json.h"
#include "scenes/input_error.h"
#include "scenes/json_overrides.h"
#include "scenes/scene.h"
#include "scenes/value_rules.h"

namespace facet::scene::detail {

using nlohmann::json;

// A value in the document and the path that names it in error messages.
class Field {
 public:
  Field(const json& value, std::string path, const std::string& source)
      : value_(value), path_(std::move(path)), source_(source) {}

  // The document itself has no path: it is named as such.
  [[noreturn]] void fail(const std::string& rule) const {
    throw InputError(source_, 0, path_.empty() ? "the document" : path_, rule);
  }

  const json& value() const { return value_; }
  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }
  bool has(const char* key) const { return value_.contains(key); }

  Field operator[](const char* key) const { return {value_.at(key), child(key), source_}; }
  Field operator[](std::size_t i) const { return {value_.at(i), path_ + "[" + std::to_string(i) + "]", source_}; }

  // Only `keys` may appear (materials/strict_json.h).
  const Field& object(std::initializer_list<const char*> keys) const {
    if (!value_.is_object()) fail("expected an object");
    const std::span<const char* const> known(keys.begin(), keys.size());
    if (const std::optional<std::string> key = materials::findUnknownKey(value_, known))
      (*this)[key->c_str()].fail(materials::unknownFieldRule(known));
    return *this;
  }

  double number(double lo = -HUGE_VAL, double hi = HUGE_VAL) const {
    if (!value_.is_number()) fail("expected a number");
    double x = value_.get<double>();
    if (!std::isfinite(x)) fail("must be finite");
    if (const std::optional<std::string> rule = rangeRule(x, lo, hi)) fail(*rule);
    return x;
  }

  int integer(int lo, int hi) const {
    double x = number(lo, hi);
    if (x != std::floor(x)) fail("expected a whole number");
    return int(x);
  }

  bool boolean() const {
    if (!value_.is_boolean()) fail("expected true or false");
    return value_.get<bool>();
  }

  std::string string() const {
    if (!value_.is_string()) fail("expected a string");
    return value_.get<std::string>();
  }

  glm::dvec3 vec3() const {
    if (!value_.is_array() || value_.size() != 3) fail("expected an array of 3 numbers");
    return {(*this)[std::size_t(0)].number(), (*this)[1].number(), (*this)[2].number()};
  }

  // One of `options`, by name; anything else is an error listing them.
  template <class T>
  T choice(std::initializer_list<std::pair<const char*, T>> options) const {
    const std::string name = string();
    std::string list;
    for (const auto& [key, value] : options) {
      if (name == key) return value;
      list += (list.empty() ? "" : ", ") + std::string(key);
    }
    fail("unknown value '" + name + "' (expected one of: " + list + ")");
  }

  glm::dvec3 direction() const {
    glm::dvec3 d = vec3();
    if (glm::length(d) < 1e-12) fail("a direction must not be the zero vector");
    return glm::normalize(d);
  }

 private:
  std::string child(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  const json& value_;
  std::string path_;
  const std::string& source_;
};

// The "render" object into `r`.
void readRender(const Field& f, RenderSettings& r);
// The "camera" object over `start`: the fields it gives replace start's.
Camera readCamera(const Field& f, Camera start);
// The "environment" object, its map read relative to `sceneFile`; with
// `start`, an object that names neither file nor color keeps start's map
// and the fields it gives replace start's.
Environment readEnvironment(const Field& f, const std::filesystem::path& sceneFile,
                            const std::optional<Environment>& start = std::nullopt);

// A string that ends in .json (any case) names a material file; any other
// names a material of the scene or a preset.
bool namesMaterialFile(std::string_view text);
// A material entry (scene_json_materials.cpp): an object of material
// fields, which may "extends" a material file, or a material file's name,
// read relative to `relativeTo`, the file the entry is written in; its
// textures are appended to `textures`.
materials::Material readMaterial(const Field& f, const std::filesystem::path& relativeTo,
                                 std::vector<Texture>& textures);
// Every material entry that names a file and that an override reaches into
// becomes {"extends": FILE}, so that the override sets a field over the file's.
void expandMaterialFiles(json& document, std::span<const JsonOverride> overrides);

}  // namespace facet::scene::detail
