#include "scenes/json_overrides.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>
#include <variant>
#include <vector>

namespace facet::scene {
namespace {

using nlohmann::json;
using Step = std::variant<std::string, std::size_t>;  // a key or an array index

// "a.b[2].c" into a, b, 2, c: keys joined by '.', each followed by any
// number of [INDEX]; nothing for a malformed path.
std::optional<std::vector<Step>> steps(const std::string& path) {
  std::vector<Step> result;
  std::size_t i = 0;
  while (true) {
    const std::size_t end = std::min(path.find_first_of(".[", i), path.size());
    if (end == i) return std::nullopt;  // an empty key
    result.emplace_back(path.substr(i, end - i));
    i = end;
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1 || close - i > 10) return std::nullopt;
      std::size_t index = 0;
      for (std::size_t d = i + 1; d < close; ++d) {
        if (!std::isdigit(static_cast<unsigned char>(path[d]))) return std::nullopt;
        index = 10 * index + std::size_t(path[d] - '0');
      }
      result.emplace_back(index);
      i = close + 1;
    }
    if (i == path.size()) return result;
    if (path[i] != '.') return std::nullopt;
    ++i;
  }
}

std::string typeName(const json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  if (value.is_string()) return "a string";
  if (value.is_boolean()) return "a boolean";
  return "a number";
}

json parsedValue(const std::string& text) {
  // Without exceptions: a word that is not JSON is the string it spells.
  json value = json::parse(text, nullptr, false);
  return value.is_discarded() ? json(text) : value;
}

}  // namespace

JsonOverride parseJsonOverride(const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos)
    throw std::invalid_argument("--set '" + assignment + "': expected PATH=VALUE, e.g. render.spp=16");
  JsonOverride o{assignment.substr(0, equals), assignment.substr(equals + 1)};
  if (!steps(o.path))
    throw std::invalid_argument("--set '" + assignment +
                                "': the path must be keys joined by '.', each optionally followed by [INDEX], e.g. "
                                "objects[0].material");
  return o;
}

void applyJsonOverride(json& document, const JsonOverride& o) {
  const std::optional<std::vector<Step>> path = steps(o.path);
  if (!path) throw std::invalid_argument("--set '" + o.text() + "': malformed path");
  auto fail = [&](const std::string& problem) { throw std::invalid_argument("--set " + o.text() + ": " + problem); };
  json* node = &document;
  std::string at;  // the path walked so far
  for (const Step& step : *path) {
    if (const std::string* key = std::get_if<std::string>(&step)) {
      if (node->is_null()) *node = json::object();
      if (!node->is_object())
        fail((at.empty() ? std::string("the document") : at) + " is " + typeName(*node) + ", not an object");
      node = &(*node)[*key];
      if (!at.empty()) at += '.';
      at += *key;
    } else {
      const std::size_t index = std::get<std::size_t>(step);
      if (!node->is_array())
        fail(at + (node->is_null() ? " is not in the scene" : " is " + typeName(*node) + ", not an array"));
      if (index >= node->size())
        fail(at + " has " + std::to_string(node->size()) + (node->size() == 1 ? " entry" : " entries") +
             " (indices from 0)");
      node = &(*node)[index];
      at += '[';
      at += std::to_string(index);
      at += ']';
    }
  }
  *node = parsedValue(o.value);
}

bool overrideConcerns(const JsonOverride& o, const std::string& field) {
  auto within = [](const std::string& inner, const std::string& outer) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
           (inner[outer.size()] == '.' || inner[outer.size()] == '[');
  };
  return field == o.path || within(field, o.path) || within(o.path, field);
}

}  // namespace facet::scene
