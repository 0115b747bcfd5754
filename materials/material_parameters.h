// The material parameters a user gives as a number, a colour or a flag, one
// row each. A row declares MaterialSpec's field, and through
// materials/parameter_table.h it is also the JSON key, the public
// facet::Material's field copy, the Python keyword and property, and the
// command-line flag (docs/architecture.md, "A new material lobe").
//
// X(type, member, key, plain, bounds, flag help):
//   type       double, glm::dvec3 (a colour: one number or three) or bool;
//   member     the field's name in MaterialSpec and in facet::Material;
//   key        the JSON key and Python name; the flag is --key with '-' for '_';
//   plain      the Material field it is copied into as given, or nullptr
//              where buildMaterial resolves it (presets, Fresnel, glTF's
//              metallic-roughness);
//   bounds     kUnitInterval, or kUnbounded where the rule is not a range;
//   flag help  the flag's help for brdf, albedo and plot, or nullptr where
//              those commands take no such flag (they evaluate the
//              reflection BRDF alone).
// A macro because it declares MaterialSpec's fields; everything else reads
// the typed table.
#pragma once

#define FACET_MATERIAL_PARAMETERS(X)                                                                              \
  X(double, alpha, "alpha", nullptr, kUnitInterval, "microfacet alpha in [0, 1] (alpha = roughness^2)")           \
  X(double, roughness, "roughness", nullptr, kUnitInterval, "perceptual roughness in [0, 1], instead of --alpha") \
  X(glm::dvec3, f0, "f0", nullptr, kUnbounded, "F(0) = c_spec for schlick (or to derive an ior): x or r,g,b")     \
  X(glm::dvec3, ior, "ior", nullptr, kUnbounded, "index of refraction for dielectric: x or r,g,b")                \
  X(glm::dvec3, eta, "eta", nullptr, kUnbounded, "conductor: real part of the complex index, r,g,b")              \
  X(glm::dvec3, k, "k", nullptr, kUnbounded, "conductor: extinction coefficient, r,g,b")                          \
  X(glm::dvec3, diffuse, "diffuse", &Material::diffuse, kUnbounded, "Lambert c_diff: x or r,g,b (default 0)")     \
  X(glm::dvec3, baseColor, "base_color", nullptr, kUnbounded,                                                     \
    "glTF's base colour, linear r,g,b or x in [0, 1], with --metallic: instead of --diffuse and --f0")            \
  X(double, metallic, "metallic", nullptr, kUnitInterval, "glTF's metallic in [0, 1], with --base-color")         \
  X(bool, energyCompensation, "energy_compensation", &Material::energyCompensation, kUnbounded, nullptr)          \
  X(double, transmission, "transmission", nullptr, kUnitInterval, nullptr)                                        \
  X(bool, thinWalled, "thin_walled", &Material::thinWalled, kUnbounded, nullptr)                                  \
  X(glm::dvec3, attenuationColor, "attenuation_color", nullptr, kUnbounded, nullptr)                              \
  X(double, attenuationDistance, "attenuation_distance", nullptr, kUnbounded, nullptr)                            \
  X(double, thickness, "thickness", &Material::thickness, kUnbounded, nullptr)                                    \
  X(double, anisotropy, "anisotropy", &Material::anisotropy, kUnitInterval,                                       \
    "anisotropy strength in [0, 1]: alpha along the tangent (the x axis) = mix(alpha, 1, s^2)")                   \
  X(double, anisotropyRotation, "anisotropy_rotation", &Material::anisotropyRotation, kUnbounded,                 \
    "the tangent's rotation about the normal from the x axis, radians")                                           \
  X(double, clearcoat, "clearcoat", &Material::clearcoat, kUnitInterval,                                          \
    "clear coat strength in [0, 1]: a GGX lobe of F(0) = 0.04 on top")                                            \
  X(double, clearcoatRoughness, "clearcoat_roughness", &Material::clearcoatRoughness, kUnitInterval,              \
    "the clear coat's perceptual roughness in [0, 1]")                                                            \
  X(glm::dvec3, sheenColor, "sheen_color", &Material::sheenColor, kUnbounded,                                     \
    "sheen color, linear RGB in [0, 1] (r,g,b or one value): a Charlie lobe between base and coat")               \
  X(double, sheenRoughness, "sheen_roughness", &Material::sheenRoughness, kUnitInterval,                          \
    "the sheen's roughness in [0, 1]")                                                                            \
  X(double, iridescence, "iridescence", &Material::iridescence, kUnitInterval, nullptr)                           \
  X(double, iridescenceIor, "iridescence_ior", &Material::iridescenceIor, kUnbounded, nullptr)                    \
  X(double, iridescenceThickness, "iridescence_thickness", &Material::iridescenceThickness, kUnbounded, nullptr)
