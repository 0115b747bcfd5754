// The material parameter table: every row is read from JSON under its key,
// copied into Material where it is plain, written back by toJson, and
// bounded where its rule is a range.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <sstream>
#include <string>
#include <type_traits>

#include "materials/material.h"
#include "materials/parameter_table.h"

namespace facet::materials {
namespace {

// A valid value of a row's type, unlike the Material's default.
template <class T>
T sample() {
  if constexpr (std::is_same_v<T, double>) return 0.25;
  if constexpr (std::is_same_v<T, bool>) return true;
  if constexpr (std::is_same_v<T, glm::dvec3>) return glm::dvec3(0.5, 0.25, 0.125);
}

template <class T>
nlohmann::json toJsonValue(const T& value) {
  if constexpr (std::is_same_v<T, glm::dvec3>) return {value.x, value.y, value.z};
  else return value;
}

MaterialSpec read(const nlohmann::json& json) { return materialSpecFromJson(json, "test.json"); }
Material build(const nlohmann::json& json) {
  return buildMaterial(read(json), [](std::string_view field) { return std::string(field); });
}

TEST(MaterialParameterTable, KeysAreUniqueAndNoFlagIsABool) {
  std::set<std::string> keys;
  forEachParameter([&](const auto& row) {
    EXPECT_TRUE(keys.insert(row.key).second) << row.key;
    using T = typename std::decay_t<decltype(row)>::Value;
    if constexpr (std::is_same_v<T, bool>) {
      EXPECT_EQ(row.flagHelp, nullptr) << row.key;
    }
  });
}

TEST(MaterialParameterTable, EveryRowIsReadFromItsJsonKey) {
  forEachParameter([&](const auto& row) {
    using T = typename std::decay_t<decltype(row)>::Value;
    const MaterialSpec spec = read({{row.key, toJsonValue(sample<T>())}});
    ASSERT_TRUE((spec.*row.spec).has_value()) << row.key;
    EXPECT_EQ(*(spec.*row.spec), sample<T>()) << row.key;
  });
}

// Two materials between them give every plain row: the layers need an
// opaque base, a thin wall's fields a transmissive one.
TEST(MaterialParameterTable, EveryPlainRowReachesMaterialAndToJson) {
  const nlohmann::json opaque = {{"alpha", 0.1},
                                 {"f0", 0.04},
                                 {"energy_compensation", true},
                                 {"diffuse", 0.5},
                                 {"anisotropy", 0.5},
                                 {"anisotropy_rotation", 0.3},
                                 {"clearcoat", 0.5},
                                 {"clearcoat_roughness", 0.2},
                                 {"sheen_color", {0.5, 0.25, 0.125}},
                                 {"sheen_roughness", 0.4},
                                 {"iridescence", 0.75},
                                 {"iridescence_ior", 1.6},
                                 {"iridescence_thickness", 320.0}};
  const nlohmann::json thin = {{"alpha", 0.1}, {"ior", 1.5}, {"transmission", 1}, {"thin_walled", true},
                               {"thickness", 0.01}};
  forEachParameter([&](const auto& row) {
    if (!row.plain) return;
    const nlohmann::json& json = opaque.contains(row.key) ? opaque : thin;
    ASSERT_TRUE(json.contains(row.key)) << row.key << " is plain but neither material gives it";
    using T = typename std::decay_t<decltype(row)>::Value;
    const T given = *(read(json).*row.spec);
    const Material m = build(json);
    EXPECT_EQ(m.*row.plain, given) << row.key;
    EXPECT_EQ(*(read(toJson(m)).*row.spec), given) << row.key << " is not written back by toJson";
  });
}

TEST(MaterialParameterTable, EveryBoundedRowRejectsAValueOutsideItsBounds) {
  forEachParameter([&](const auto& row) {
    if (!row.bounds) return;
    nlohmann::json json = {{row.key, row.bounds->hi + 1.0}};
    if (std::string(row.key) != "alpha" && std::string(row.key) != "roughness") json["alpha"] = 0.1;
    if (std::string(row.key) == "metallic") json["base_color"] = 0.5, json.erase("alpha"), json["roughness"] = 0.5;
    try {
      build(json);
      ADD_FAILURE() << row.key << " accepted " << json.dump();
    } catch (const std::invalid_argument& e) {
      std::ostringstream rule;
      rule << row.key << ": must be in [" << row.bounds->lo << ", " << row.bounds->hi << "], got "
           << row.bounds->hi + 1.0;
      EXPECT_EQ(std::string(e.what()), rule.str()) << json.dump();
    }
  });
}

}  // namespace
}  // namespace facet::materials
