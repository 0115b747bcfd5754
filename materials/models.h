// Names of the interchangeable parts of the BRDF, as used on the command line
// and in material files, mapped to the ids of the shared shading source.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "rules/rules.h"

namespace facet::materials {

struct ModelName {
  int id;
  std::string_view name;
  std::string_view description;
};

inline constexpr ModelName kDistributions[] = {
    {rules::f64::D_GGX, "ggx", "GGX / Trowbridge-Reitz"},
    {rules::f64::D_BECKMANN, "beckmann", "Beckmann"},
    {rules::f64::D_BLINN_PHONG, "blinn-phong", "normalized Blinn-Phong, exponent 2/alpha^2 - 2"},
};

inline constexpr ModelName kGeometryTerms[] = {
    {rules::f64::G_IMPLICIT, "implicit", "G = (n.l)(n.v)"},
    {rules::f64::G_COOK_TORRANCE, "cook-torrance", "Cook-Torrance V-cavity"},
    {rules::f64::G_KELEMEN, "kelemen", "Kelemen & Szirmay-Kalos, (n.l)(n.v)/(v.h)^2"},
    {rules::f64::G_SMITH_GGX, "smith-ggx", "Smith separable, GGX microsurface"},
    {rules::f64::G_SMITH_GGX_CORRELATED, "smith-ggx-correlated", "Smith height-correlated, GGX"},
    {rules::f64::G_SMITH_BECKMANN, "smith-beckmann", "Smith separable, Beckmann microsurface"},
    {rules::f64::G_SMITH_BECKMANN_CORRELATED, "smith-beckmann-correlated", "Smith height-correlated, Beckmann"},
};

inline constexpr ModelName kFresnelTerms[] = {
    {rules::f64::F_NONE, "none", "F = 1"},
    {rules::f64::F_SCHLICK, "schlick", "Schlick from F(0) = c_spec (RGB)"},
    {rules::f64::F_DIELECTRIC, "dielectric", "exact, real index of refraction"},
    {rules::f64::F_CONDUCTOR, "conductor", "exact, complex index eta + i k per RGB channel"},
    {rules::f64::F_BLENDER_METALLIC, "blender-metallic",
     "Blender Cycles' Principled metallic: the index-1.5 dielectric curve rescaled from F(0) = c_spec"},
};

inline constexpr ModelName kSamplingTechniques[] = {
    {rules::f64::SAMPLE_COSINE, "cosine", "cosine-weighted hemisphere"},
    {rules::f64::SAMPLE_D, "d", "half vector proportional to D(m)(n.m)"},
    {rules::f64::SAMPLE_GGX_VISIBLE, "ggx-visible", "GGX distribution of visible normals"},
};

// The id of `name` in `table`; throws std::invalid_argument naming `what`
// and listing the valid names.
int parseModel(std::span<const ModelName> table, std::string_view what, std::string_view name);
std::string_view modelName(std::span<const ModelName> table, int id);
// "a, b, c" for error messages and help texts.
std::string modelList(std::span<const ModelName> table);

}  // namespace facet::materials
