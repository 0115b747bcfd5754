#include "materials/material.h"

#include <glm/common.hpp>

#include <cmath>
#include <utility>
#include <sstream>
#include <stdexcept>

#include "materials/models.h"
#include "materials/parameter_table.h"
#include "materials/presets.h"

namespace facet::materials {

namespace {

// Hammersley points per sheen albedo knot (docs/shading.md, "Sheen").
constexpr int kSheenAlbedoSamples = 2048;

template <class Params, class Vec3>
Params toParams(const Material& m) {
  Params p;
  p.d_model = m.distribution;
  p.g_model = m.geometry;
  p.f_model = m.fresnel;
  p.alpha = static_cast<decltype(p.alpha)>(m.alpha);
  p.f0 = Vec3(m.f0);
  p.eta = Vec3(m.eta);
  p.k = Vec3(m.k);
  p.metallic = 0;  // a textured transmissive material's, set per hit
  p.diffuse = Vec3(m.diffuse);
  // The tangent in the frame n = z (what facet brdf evaluates in); the
  // renderers replace it by the surface's tangent field, rotated alike.
  using Real = decltype(p.alpha);
  p.anisotropy = static_cast<Real>(m.anisotropy);
  p.tangent = Vec3(std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation), 0.0);
  // The coat's normal likewise n = z; the renderers give it the surface's
  // normal before any normal map.
  p.clearcoat = static_cast<Real>(m.clearcoat);
  p.clearcoat_alpha = static_cast<Real>(m.clearcoatRoughness * m.clearcoatRoughness);
  p.clearcoat_normal = Vec3(0.0, 0.0, 1.0);
  p.sheen_color = Vec3(m.sheenColor);
  p.sheen_alpha = static_cast<Real>(m.sheenRoughness * m.sheenRoughness);
  // The sheen's albedo knots, in double like every table; none without one.
  using Vec4 = decltype(p.sheen_albedo_near);
  const bool sheen = m.sheenColor != glm::dvec3(0.0);
  const double alpha = m.sheenRoughness * m.sheenRoughness;
  p.sheen_albedo_near = sheen ? Vec4(rules::f64::sheen_albedo_knots(alpha, 0, kSheenAlbedoSamples)) : Vec4(0.0);
  p.sheen_albedo_far = sheen ? Vec4(rules::f64::sheen_albedo_knots(alpha, 4, kSheenAlbedoSamples)) : Vec4(0.0);
  p.iridescence = static_cast<Real>(m.iridescence);
  p.iridescence_ior = static_cast<Real>(m.iridescenceIor);
  p.iridescence_thickness = static_cast<Real>(m.iridescenceThickness);
  return p;
}

}  // namespace

const std::vector<glm::dvec4>& sheenAlbedoRows() {
  static const std::vector<glm::dvec4> rows = [] {
    std::vector<glm::dvec4> knots;
    for (int j = 0; j < rules::f64::SHEEN_ROWS; ++j) {
      const double alpha = rules::f64::sheen_row_alpha(j);
      knots.push_back(rules::f64::sheen_albedo_knots(alpha, 0, kSheenAlbedoSamples));
      knots.push_back(rules::f64::sheen_albedo_knots(alpha, 4, kSheenAlbedoSamples));
    }
    return knots;
  }();
  return rows;
}

namespace {

[[noreturn]] void throwFieldError(const std::string& where, const std::string& rule) {
  throw std::invalid_argument(where + ": " + rule);
}

std::string formatNumber(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string formatVector(glm::dvec3 v) { return formatNumber(v.x) + "," + formatNumber(v.y) + "," + formatNumber(v.z); }

// A bounded parameter's range, from its row of the table.
template <class Fail>
void checkBounds(BoundedParameter parameter, double value, const Fail& fail) {
  const auto [lo, hi] = parameter.bounds;
  if (!(value >= lo && value <= hi))  // also rejects NaN
    fail(parameter.key, "must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], got " + formatNumber(value));
}

// The parameters given as they are used; the checks below see them in `m`.
void copyPlainParameters(const MaterialSpec& spec, Material& m) {
  forEachParameter([&](const auto& row) {
    if (row.plain && spec.*row.spec) m.*row.plain = *(spec.*row.spec);
  });
}

// The transmission fields of `spec` (or its preset) into `m`, whose
// transmission factor and Fresnel are already resolved.
template <class Fail>
void checkTransmission(const MaterialSpec& spec, const Preset* preset, Material& m, const Fail& fail) {
  const bool transmissive = isTransmissive(m);
  auto transmissiveOnly = [&](std::string_view field, bool given) {
    if (given && !transmissive) fail(field, "is only used by a transmissive material (transmission > 0)");
  };
  transmissiveOnly("thin_walled", spec.thinWalled.has_value());
  transmissiveOnly("attenuation_color", spec.attenuationColor.has_value());
  transmissiveOnly("attenuation_distance", spec.attenuationDistance.has_value());
  transmissiveOnly("thickness", spec.thickness.has_value());
  if (!transmissive) return;
  const std::string_view indexField = spec.ior ? "ior" : spec.f0 ? "f0" : "preset";
  if (m.fresnel != rules::f64::F_DIELECTRIC)
    fail("fresnel", "a transmissive material (transmission > 0) takes fresnel 'dielectric', not '" +
                        std::string(modelName(kFresnelTerms, m.fresnel)) + "'");
  if (m.distribution != rules::f64::D_GGX)
    fail("distribution", "a transmissive material samples GGX's visible normals: must be 'ggx'");
  if (m.geometry != rules::f64::G_SMITH_GGX_CORRELATED)
    fail("geometry",
         "a transmissive material's BTDF uses Smith's height-correlated GGX: must be "
         "'smith-ggx-correlated'");
  if (!(m.eta.x == m.eta.y && m.eta.x == m.eta.z))
    fail(indexField, "a transmissive material has one index of refraction (no dispersion), got " + formatVector(m.eta));
  if (!(m.eta.x >= 1.0))
    fail(indexField, "a transmissive material's index of refraction (inside over outside) must be >= 1, got " +
                         formatNumber(m.eta.x));
  if (preset) m.attenuationColor = preset->attenuationColor, m.attenuationDistance = preset->attenuationDistance;
  if (spec.attenuationColor) {
    for (int i = 0; i < 3; ++i)
      if (!((*spec.attenuationColor)[i] >= 0.0 && (*spec.attenuationColor)[i] <= 1.0))
        fail("attenuation_color", "every component must be in [0, 1], got " + formatVector(*spec.attenuationColor));
    m.attenuationColor = *spec.attenuationColor;
  }
  if (spec.attenuationDistance) {
    if (!(*spec.attenuationDistance > 0.0))  // also rejects NaN
      fail("attenuation_distance",
           "must be > 0 (leave it out for no absorption), got " + formatNumber(*spec.attenuationDistance));
    m.attenuationDistance = *spec.attenuationDistance;
  }
  if (spec.thickness) {
    if (!m.thinWalled) fail("thickness", "is only used by a thin-walled material (thin_walled true)");
    if (!(*spec.thickness >= 0.0 && std::isfinite(*spec.thickness)))
      fail("thickness", "must be finite and >= 0, got " + formatNumber(*spec.thickness));
  }
}

// The anisotropy fields of `spec`, copied into `m`, whose models and
// transmission are already resolved.
template <class Fail>
void checkAnisotropy(const MaterialSpec& spec, const Material& m, const Fail& fail) {
  if (spec.anisotropy) checkBounds(bounded(&MaterialSpec::anisotropy), *spec.anisotropy, fail);
  if (spec.anisotropyRotation) {
    if (!std::isfinite(*spec.anisotropyRotation))
      fail("anisotropy_rotation", "must be a finite angle in radians, got " + formatNumber(*spec.anisotropyRotation));
    if (!spec.anisotropy) fail("anisotropy_rotation", "is only used with anisotropy (give anisotropy too)");
  }
  if (m.anisotropy == 0.0) return;
  if (m.distribution == rules::f64::D_BLINN_PHONG)
    fail("anisotropy", "needs distribution 'ggx' or 'beckmann' (Blinn-Phong has no anisotropic form here)");
  if (isTransmissive(m)) fail("anisotropy", "is not defined for a transmissive material (transmission > 0)");
}

// The clear coat fields of `spec`, copied into `m`, whose transmission is
// already resolved.
template <class Fail>
void checkClearcoat(const MaterialSpec& spec, const Material& m, const Fail& fail) {
  if (spec.clearcoat) checkBounds(bounded(&MaterialSpec::clearcoat), *spec.clearcoat, fail);
  if (spec.clearcoatRoughness) {
    checkBounds(bounded(&MaterialSpec::clearcoatRoughness), *spec.clearcoatRoughness, fail);
    if (!spec.clearcoat) fail("clearcoat_roughness", "is only used with clearcoat (give clearcoat too)");
  }
  if (m.clearcoat > 0.0 && isTransmissive(m))
    fail("clearcoat", "is not defined for a transmissive material (transmission > 0)");
}

// The sheen fields of `spec`, copied into `m`, whose transmission is resolved.
template <class Fail>
void checkSheen(const MaterialSpec& spec, const Material& m, const Fail& fail) {
  for (double channel : {m.sheenColor.x, m.sheenColor.y, m.sheenColor.z})
    if (!(channel >= 0.0 && channel <= 1.0))  // also rejects NaN
      fail("sheen_color", "each channel must be in [0, 1], got " + formatNumber(channel));
  if (spec.sheenRoughness) checkBounds(bounded(&MaterialSpec::sheenRoughness), *spec.sheenRoughness, fail);
  if (spec.sheenRoughness && !spec.sheenColor)
    fail("sheen_roughness", "is only used with sheen_color (give sheen_color too)");
  if (m.sheenColor != glm::dvec3(0.0) && isTransmissive(m))
    fail("sheen_color", "is not defined for a transmissive material (transmission > 0)");
}

// The iridescence fields of `spec`, copied into `m`, whose transmission is
// resolved: the film's index within the optical constants' bounds, its
// thickness finite, both only with the factor.
template <class Fail>
void checkIridescence(const MaterialSpec& spec, const Material& m, const Fail& fail) {
  if (spec.iridescence) checkBounds(bounded(&MaterialSpec::iridescence), *spec.iridescence, fail);
  if (spec.iridescenceIor && !(*spec.iridescenceIor >= 1.0 && *spec.iridescenceIor <= kMaxOpticalConstant))
    fail("iridescence_ior", "must be in [1, " + formatNumber(kMaxOpticalConstant) +
                                "] (the extension's minimum is 1), got " + formatNumber(*spec.iridescenceIor));
  if (spec.iridescenceThickness && !(*spec.iridescenceThickness >= 0.0 && std::isfinite(*spec.iridescenceThickness)))
    fail("iridescence_thickness",
         "must be finite and >= 0 (nanometres), got " + formatNumber(*spec.iridescenceThickness));
  for (const auto& [field, given] : {std::pair{"iridescence_ior", spec.iridescenceIor.has_value()},
                                     std::pair{"iridescence_thickness", spec.iridescenceThickness.has_value()}})
    if (given && !spec.iridescence) fail(field, "is only used with iridescence (give iridescence too)");
  if (m.iridescence > 0.0 && isTransmissive(m))
    fail("iridescence", "is not defined for a transmissive material (transmission > 0)");
}

// glTF's metallic-roughness parameters (docs/shading.md, "Materials"):
// base_color and metallic give c_diff = base (1 - metallic) and Schlick's
// F(0) = mix(0.04, base, metallic), as glTF's textured rule does per hit
// (rules/shading/textured_material.h). They take the place of diffuse, f0,
// a preset and the other Fresnel terms, so none of those may be given too.
template <class Fail>
MaterialSpec withMetallicRoughness(MaterialSpec spec, const Fail& fail) {
  if (!spec.baseColor && !spec.metallic) return spec;
  if (!spec.baseColor || !spec.metallic)
    fail(spec.baseColor ? "metallic" : "base_color",
         "base_color and metallic are given together (glTF's default metallic of 1 would make any colour a metal)");
  const std::pair<const char*, bool> others[] = {{"preset", spec.preset.has_value()},
                                                 {"diffuse", spec.diffuse.has_value()},
                                                 {"f0", spec.f0.has_value()},
                                                 {"ior", spec.ior.has_value()},
                                                 {"eta", spec.eta.has_value()},
                                                 {"k", spec.k.has_value()},
                                                 {"transmission", spec.transmission.value_or(0.0) > 0.0}};
  for (auto [field, given] : others)
    if (given) fail(field, "is not combined with base_color and metallic, which give c_diff and F(0)");
  if (spec.fresnel && *spec.fresnel != "schlick")
    fail("fresnel", "must be 'schlick' with base_color and metallic (glTF's Fresnel), got '" + *spec.fresnel + "'");
  for (int i = 0; i < 3; ++i)
    if (!((*spec.baseColor)[i] >= 0.0 && (*spec.baseColor)[i] <= 1.0))
      fail("base_color", "each channel must be in [0, 1], got " + formatNumber((*spec.baseColor)[i]));
  checkBounds(bounded(&MaterialSpec::metallic), *spec.metallic, fail);
  spec.diffuse = *spec.baseColor * (1.0 - *spec.metallic);
  spec.f0 = glm::mix(glm::dvec3(0.04), *spec.baseColor, *spec.metallic);
  spec.fresnel = "schlick";
  return spec;
}

// The preset `spec` names, or nullptr for none.
template <class Fail>
const Preset* namedPreset(const MaterialSpec& spec, const Fail& fail) {
  if (!spec.preset) return nullptr;
  const Preset* preset = findPreset(*spec.preset);
  if (!preset) {
    std::string names;
    for (const Preset& p : presets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
    fail("preset", "unknown preset '" + *spec.preset + "' (expected one of: " + names + ")");
  }
  return preset;
}

// GGX alpha, given as alpha or as roughness = sqrt(alpha), one of the two.
template <class Fail>
double alphaOf(const MaterialSpec& spec, const Fail& fail) {
  if (spec.alpha && spec.roughness) fail("alpha", "give alpha or roughness, not both");
  if (!spec.alpha && !spec.roughness) fail("alpha", "required (or roughness = sqrt(alpha))");
  if (spec.alpha) {
    checkBounds(bounded(&MaterialSpec::alpha), *spec.alpha, fail);
    return *spec.alpha;
  }
  checkBounds(bounded(&MaterialSpec::roughness), *spec.roughness, fail);
  return *spec.roughness * *spec.roughness;
}

// An index of refraction or extinction coefficient, each component in
// (0, kMaxOpticalConstant], or [0, ...] where zero is physical (extinction).
template <class Fail>
void checkOpticalConstant(std::string_view field, const glm::dvec3& value, bool zeroAllowed, const Fail& fail) {
  for (int i = 0; i < 3; ++i)
    if (!((zeroAllowed ? value[i] >= 0.0 : value[i] > 0.0) && value[i] <= kMaxOpticalConstant))  // also NaN
      fail(field, std::string("every component must be in ") + (zeroAllowed ? "[0, " : "(0, ") +
                      formatNumber(kMaxOpticalConstant) + "], got " + formatVector(value));
}

// The parameters m's Fresnel term reads, from `spec` and `f0` (given or the
// preset's); a parameter the term does not read may not be given.
template <class Fail>
void resolveFresnel(const MaterialSpec& spec, const std::optional<glm::dvec3>& f0, Material& m, const Fail& fail) {
  std::string fresnelName(modelName(kFresnelTerms, m.fresnel));
  auto onlyFor = [&](std::string_view field, bool given, bool used, std::string_view users) {
    if (given && !used) fail(field, "is only used by fresnel " + std::string(users) + ", not '" + fresnelName + "'");
  };
  onlyFor("f0", spec.f0.has_value(),
          m.fresnel == rules::f64::F_SCHLICK || m.fresnel == rules::f64::F_DIELECTRIC ||
              m.fresnel == rules::f64::F_BLENDER_METALLIC,
          "'schlick', 'dielectric' or 'blender-metallic'");
  onlyFor("ior", spec.ior.has_value(), m.fresnel == rules::f64::F_DIELECTRIC, "'dielectric'");
  onlyFor("eta", spec.eta.has_value(), m.fresnel == rules::f64::F_CONDUCTOR, "'conductor'");
  onlyFor("k", spec.k.has_value(), m.fresnel == rules::f64::F_CONDUCTOR, "'conductor'");

  switch (m.fresnel) {
    case rules::f64::F_SCHLICK:
    case rules::f64::F_BLENDER_METALLIC:
      if (!f0) fail("f0", "required by fresnel '" + fresnelName + "' (or give a preset)");
      m.f0 = *f0;
      break;
    case rules::f64::F_DIELECTRIC:
      if (spec.ior) {
        m.eta = *spec.ior;
      } else if (f0) {
        for (int i = 0; i < 3; ++i)
          if (!((*f0)[i] < 1.0)) fail("f0", "must be < 1 to derive an index of refraction");
        m.eta = {iorFromF0(f0->x), iorFromF0(f0->y), iorFromF0(f0->z)};
        for (int i = 0; i < 3; ++i)
          if (!(m.eta[i] <= kMaxOpticalConstant))
            fail("f0", "gives an index of refraction of " + formatNumber(m.eta[i]) + ", above the largest, " +
                           formatNumber(kMaxOpticalConstant) + ": got " + formatVector(*f0));
      } else {
        fail("ior", "required by fresnel 'dielectric' (or give f0 or a preset)");
      }
      break;
    case rules::f64::F_CONDUCTOR:
      if (!spec.eta || !spec.k) fail(spec.eta ? "k" : "eta", "required by fresnel 'conductor'");
      m.eta = *spec.eta;
      m.k = *spec.k;
      break;
  }
}

}  // namespace

rules::f64::TransmissionParams transmissionParams64(const Material& material) {
  rules::f64::TransmissionParams t;
  t.transmission = material.transmission;
  t.ior = material.eta.x;
  t.thin_walled = material.thinWalled;
  t.sigma = rules::f64::absorption_coefficient(material.attenuationColor, material.attenuationDistance);
  t.thickness = material.thickness;
  return t;
}

rules::f64::BrdfParams toParams64(const Material& material) {
  return toParams<rules::f64::BrdfParams, glm::dvec3>(material);
}

rules::f32::BrdfParams toParams32(const Material& material) {
  return toParams<rules::f32::BrdfParams, glm::vec3>(material);
}

Material buildMaterial(const MaterialSpec& given,
                       const std::function<std::string(std::string_view field)>& describeField) {
  auto fail = [&](std::string_view field, const std::string& rule) { throwFieldError(describeField(field), rule); };
  const MaterialSpec spec = withMetallicRoughness(given, fail);
  auto checkReflectance = [&](std::string_view field, glm::dvec3 v) {
    for (int i = 0; i < 3; ++i)
      if (!(v[i] >= 0.0 && v[i] <= 1.0)) fail(field, "every component must be in [0, 1], got " + formatVector(v));
  };

  Material m;
  m.name = spec.name;
  copyPlainParameters(spec, m);
  const Preset* preset = namedPreset(spec, fail);
  if (preset && m.name.empty()) m.name = preset->name;

  auto parse = [&](std::span<const ModelName> table, std::string_view field, const std::optional<std::string>& value,
                   int fallback) {
    if (!value) return fallback;
    try {
      return parseModel(table, field, *value);
    } catch (const std::invalid_argument& e) {
      throwFieldError(describeField(field), e.what());
    }
  };
  bool hasFresnelParameter = spec.f0 || spec.ior || spec.eta || spec.k || preset;
  if (spec.transmission) checkBounds(bounded(&MaterialSpec::transmission), *spec.transmission, fail);
  m.transmission = spec.transmission.value_or(preset ? preset->transmission : 0.0);
  const bool transmissive = isTransmissive(m);
  const int defaultFresnel = transmissive          ? rules::f64::F_DIELECTRIC
                             : hasFresnelParameter ? rules::f64::F_SCHLICK
                                                   : rules::f64::F_NONE;
  m.distribution = parse(kDistributions, "distribution", spec.distribution, rules::f64::D_GGX);
  m.geometry = parse(kGeometryTerms, "geometry", spec.geometry, rules::f64::G_SMITH_GGX_CORRELATED);
  m.fresnel = parse(kFresnelTerms, "fresnel", spec.fresnel, defaultFresnel);

  m.alpha = alphaOf(spec, fail);

  std::optional<glm::dvec3> f0 = spec.f0;
  if (!f0 && preset) f0 = preset->f0_linear;
  if (spec.f0) checkReflectance("f0", *spec.f0);
  if (spec.ior) checkOpticalConstant("ior", *spec.ior, false, fail);
  if (spec.eta) checkOpticalConstant("eta", *spec.eta, false, fail);
  if (spec.k) checkOpticalConstant("k", *spec.k, true, fail);

  resolveFresnel(spec, f0, m, fail);

  if (spec.diffuse) checkReflectance("diffuse", *spec.diffuse);
  checkTransmission(spec, preset, m, fail);
  checkAnisotropy(spec, m, fail);
  checkClearcoat(spec, m, fail);
  checkSheen(spec, m, fail);
  checkIridescence(spec, m, fail);
  return m;
}

}  // namespace facet::materials
