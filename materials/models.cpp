#include "materials/models.h"

#include <stdexcept>

namespace facet::materials {

int parseModel(std::span<const ModelName> table, std::string_view what, std::string_view name) {
  for (const ModelName& model : table)
    if (model.name == name) return model.id;
  throw std::invalid_argument("unknown " + std::string(what) + " '" + std::string(name) +
                              "' (expected one of: " + modelList(table) + ")");
}

std::string_view modelName(std::span<const ModelName> table, int id) {
  for (const ModelName& model : table)
    if (model.id == id) return model.name;
  throw std::invalid_argument("no model with id " + std::to_string(id));
}

std::string modelList(std::span<const ModelName> table) {
  std::string list;
  for (const ModelName& model : table) {
    if (!list.empty()) list += ", ";
    list += model.name;
  }
  return list;
}

}  // namespace facet::materials
