// A material: the choice of D, G and F plus their parameters, assembled from
// a preset, command-line flags or a JSON file, validated once.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "materials/material_parameters.h"
#include "rules/rules.h"

namespace facet::materials {

// A texture a material reads, an index into the scene's textures, and the
// KHR_texture_transform of its coordinates.
struct TextureSlot {
  int texture = -1;  // none
  glm::dvec2 offset{0.0};
  double rotation = 0.0;  // radians
  glm::dvec2 scale{1.0};
  int texCoord = 0;  // the set of texture coordinates it reads: 0 TEXCOORD_0, 1 TEXCOORD_1
};

// glTF's metallic-roughness parameters, kept for a textured material: its
// textures modulate them per hit, which then map to diffuse, f0 and alpha
// as for an untextured one (docs/shading.md, "glTF materials").
struct MaterialTextures {
  glm::dvec3 baseColor{1.0};
  double metallic = 1.0;
  double roughness = 1.0;
  TextureSlot baseColorTexture;          // sRGB; RGB multiplies baseColor
  TextureSlot metallicRoughnessTexture;  // G multiplies roughness, B metallic
  TextureSlot normalTexture;             // tangent space, XY scaled by normalScale
  double normalScale = 1.0;
  TextureSlot occlusionTexture;  // R scales the environment's light, by occlusionStrength
  double occlusionStrength = 1.0;
  TextureSlot emissiveTexture;  // sRGB; RGB multiplies emission
  // KHR_materials_unlit: the base colour (factor, texture and vertex colour)
  // is emitted, in place of the emission.
  bool unlit = false;
  // The layers' textures (rules/shading/textured_material.h,
  // textured_layers): the coat's strength (R) and roughness (G) and its
  // normal map, the sheen's colour (sRGB), the anisotropy's direction (RG)
  // and strength (B).
  TextureSlot clearcoatTexture;
  TextureSlot clearcoatRoughnessTexture;
  TextureSlot clearcoatNormalTexture;
  double clearcoatNormalScale = 1.0;
  TextureSlot sheenColorTexture;
  // KHR_materials_sheen's roughness texture: A scales sheenRoughness, the
  // factor, per hit (its albedo knots read between sheenAlbedoRows).
  TextureSlot sheenRoughnessTexture;
  double sheenRoughness = 0.0;
  TextureSlot anisotropyTexture;
  // KHR_materials_transmission's texture: R scales the transmission factor.
  TextureSlot transmissionTexture;
  // The dielectric's F(0) (rules/shading/textured_material.h,
  // dielectric_specular_f0): F(0) of KHR_materials_ior's index times
  // KHR_materials_specular's colour factor, its factor, and its textures,
  // specularColorTexture's RGB (sRGB) and specularTexture's A.
  glm::dvec3 specularColor{0.04};
  double specular = 1.0;
  TextureSlot specularTexture;
  TextureSlot specularColorTexture;
  // KHR_materials_iridescence's textures: R scales the film's factor, G
  // places its thickness between the extension's minimum and its maximum
  // (the material's iridescenceThickness).
  TextureSlot iridescenceTexture;
  TextureSlot iridescenceThicknessTexture;
  double iridescenceThicknessMinimum = 100.0;  // nanometres
};

struct Material {
  std::string name;
  int distribution = rules::f64::D_GGX;
  int geometry = rules::f64::G_SMITH_GGX_CORRELATED;
  int fresnel = rules::f64::F_SCHLICK;
  double alpha = 0.25;  // microfacet alpha = perceptual roughness^2
  glm::dvec3 f0{0.04};  // used by Schlick
  glm::dvec3 eta{1.5};  // index of refraction (dielectric) or its real part (conductor)
  glm::dvec3 k{0.0};    // extinction coefficient (conductor)
  glm::dvec3 diffuse{0.0};
  glm::dvec3 emission{0.0};  // radiance the surface emits, added to what it reflects
  // Multiple-scattering compensation of the specular lobe (docs/shading.md,
  // "Energy compensation"); off keeps the course's single-scattering model.
  bool energyCompensation = false;
  std::optional<MaterialTextures> textures;  // set when the material reads any texture
  // Transmission (docs/shading.md, "Transmission"): glTF's transmission
  // factor replaces that share of the diffuse base by a rough dielectric
  // BTDF of index eta.x; inside, light keeps attenuationColor of itself over
  // attenuationDistance (Beer-Lambert). A thin wall transmits without
  // bending and absorbs over `thickness` instead.
  double transmission = 0.0;
  bool thinWalled = false;
  glm::dvec3 attenuationColor{1.0};
  double attenuationDistance = std::numeric_limits<double>::infinity();
  double thickness = 0.0;
  // Anisotropy (docs/shading.md, "Anisotropy"): KHR_materials_anisotropy's
  // strength in [0, 1] (alpha along the tangent = mix(alpha, 1, strength^2))
  // and the tangent's rotation about the normal, radians.
  double anisotropy = 0.0;
  double anisotropyRotation = 0.0;
  // Clear coat (docs/shading.md, "Clear coat"): KHR_materials_clearcoat's
  // strength in [0, 1] and the coat's perceptual roughness (its alpha is the
  // square), a GGX lobe of F(0) = 0.04 over the rest.
  double clearcoat = 0.0;
  double clearcoatRoughness = 0.0;
  // Sheen (docs/shading.md, "Sheen"): KHR_materials_sheen's color (linear
  // RGB in [0, 1]; 0 is no sheen) and roughness (its alpha is the square),
  // a Charlie lobe between the base and any coat.
  glm::dvec3 sheenColor{0.0};
  double sheenRoughness = 0.0;
  // Iridescence (docs/shading.md, "Iridescence"): KHR_materials_iridescence's
  // factor in [0, 1] (0 is no film), the film's index and its thickness in
  // nanometres, the extension's defaults.
  double iridescence = 0.0;
  double iridescenceIor = 1.3;
  double iridescenceThickness = 400.0;
};

// The largest index of refraction (ior, eta) or extinction coefficient (k)
// a material may have. The Fresnel terms raise them to the fourth power in
// float on the GPU, which stays finite up to here; materials in visible
// light stay below 10 (docs/reliability.md, "Limits").
inline constexpr double kMaxOpticalConstant = 1000.0;

// Whether a material transmits any light.
inline bool isTransmissive(const Material& material) { return material.transmission > 0.0; }

// Its transmission as the shared rules take it (rules/shading/transmissive_continuation.h).
rules::f64::TransmissionParams transmissionParams64(const Material& material);

rules::f64::BrdfParams toParams64(const Material& material);

// The sheen's albedo knots at each row of rules/shading/sheen.h's
// SHEEN_ROWS (sheen_row_alpha), near and far in turn, computed once: for
// the sheens whose roughness a texture sets per hit.
const std::vector<glm::dvec4>& sheenAlbedoRows();
rules::f32::BrdfParams toParams32(const Material& material);

// What a user wrote, before validation. Field names are the JSON keys; the
// command line uses the same names as flags. Besides the name and the
// models' names, one optional field a row of materials/material_parameters.h
// (alpha, roughness, f0, ..., sheenRoughness).
struct MaterialSpec {
  std::string name;
  std::optional<std::string> preset, distribution, geometry, fresnel;
#define FACET_MATERIAL_SPEC_FIELD(type, member, ...) std::optional<type> member;
  FACET_MATERIAL_PARAMETERS(FACET_MATERIAL_SPEC_FIELD)
#undef FACET_MATERIAL_SPEC_FIELD
};

// Validates and resolves a spec. Throws std::invalid_argument whose message
// starts with describeField(<field>) and states the rule that was broken.
// Defaults: ggx, smith-ggx-correlated, schlick (none when no F parameter and
// no preset is given), diffuse 0.
Material buildMaterial(const MaterialSpec& spec,
                       const std::function<std::string(std::string_view field)>& describeField);

// JSON material format, documented in docs/shading.md. Errors name the file
// (source) and the field.
MaterialSpec materialSpecFromJson(const nlohmann::json& json, std::string_view source);
Material loadMaterial(const std::filesystem::path& path);
nlohmann::json toJson(const Material& material);

}  // namespace facet::materials
