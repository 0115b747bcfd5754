// The rule facet's JSON readers share (material files here, scene files in
// scenes/): only known keys may appear, so a misspelt key is an error, not
// silently ignored.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <span>
#include <string>

namespace facet::materials {

// The first key of `object` that is not one of `known`; none when all are.
inline std::optional<std::string> findUnknownKey(const nlohmann::json& object, std::span<const char* const> known) {
  for (const auto& item : object.items()) {
    bool listed = false;
    for (const char* key : known) listed = listed || item.key() == key;
    if (!listed) return item.key();
  }
  return std::nullopt;
}

// What an unknown key is told: "unknown field (expected one of: a, b, c)".
inline std::string unknownFieldRule(std::span<const char* const> known) {
  std::string list;
  for (const char* key : known) list += (list.empty() ? "" : ", ") + std::string(key);
  return "unknown field (expected one of: " + list + ")";
}

}  // namespace facet::materials
