// The material parameters of materials/material_parameters.h as a typed
// table: each row holds the member pointers of the places the parameter
// reaches, so a reader walks the rows instead of naming each field.
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "facet/scene.h"
#include "materials/material.h"

namespace facet::materials {

// A closed interval a number must lie in.
struct Bounds {
  double lo = 0.0, hi = 0.0;
};
inline constexpr std::optional<Bounds> kUnitInterval = Bounds{0.0, 1.0};
inline constexpr std::optional<Bounds> kUnbounded = std::nullopt;

template <class T, class Public>
struct Parameter {
  using Value = T;
  using PublicValue = Public;
  const char* key;
  std::optional<T> MaterialSpec::*spec;
  Public v0::Material::*api;
  T Material::*plain;  // nullptr: buildMaterial resolves it
  std::optional<Bounds> bounds;
  const char* flagHelp;  // nullptr: no flag
};

// `plain` takes nullptr, so only the spec's field deduces the value type.
template <class T, class Public>
Parameter(const char*, std::optional<T> MaterialSpec::*, Public v0::Material::*, std::type_identity_t<T> Material::*,
          std::optional<Bounds>, const char*) -> Parameter<T, Public>;

#define FACET_MATERIAL_PARAMETER_ROW(type, member, key, plain, bounds, flagHelp) \
  Parameter{key, &MaterialSpec::member, &v0::Material::member, plain, bounds, flagHelp},
inline constexpr std::tuple kMaterialParameters{FACET_MATERIAL_PARAMETERS(FACET_MATERIAL_PARAMETER_ROW)};
#undef FACET_MATERIAL_PARAMETER_ROW

inline constexpr std::size_t kMaterialParameterCount = std::tuple_size_v<decltype(kMaterialParameters)>;

// Calls f(row) for every row, in the table's order; with an index, f(row, i).
template <class F>
constexpr void forEachParameter(F&& f) {
  std::apply([&](const auto&... row) { (f(row), ...); }, kMaterialParameters);
}
template <class F>
constexpr void forEachParameterIndexed(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::get<I>(kMaterialParameters), I), ...);
  }(std::make_index_sequence<kMaterialParameterCount>());
}

// The key and bounds of the row of spec field `member`, for a rule that
// checks its range where the order of buildMaterial's checks puts it. A
// field with no row, or a row with no bounds, does not compile.
struct BoundedParameter {
  const char* key;
  Bounds bounds;
};
consteval BoundedParameter bounded(std::optional<double> MaterialSpec::*member) {
  std::optional<BoundedParameter> found;
  forEachParameter([&](const auto& row) {
    if constexpr (std::is_same_v<typename std::decay_t<decltype(row)>::Value, double>)
      if (row.spec == member && row.bounds) found = BoundedParameter{row.key, *row.bounds};
  });
  if (!found) throw std::logic_error("not a bounded material parameter");
  return *found;
}

}  // namespace facet::materials
