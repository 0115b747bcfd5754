// The transmission fields of the JSON material format: defaults, presets,
// round trips and the errors that name the field and the rule.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "materials/material.h"
#include "materials/presets.h"

namespace facet::materials {
namespace {

Material build(const std::string& text) {
  const std::string source = "glass.json";
  return buildMaterial(materialSpecFromJson(nlohmann::json::parse(text), source),
                       [&](std::string_view field) { return source + ": field '" + std::string(field) + "'"; });
}

std::string errorOf(const std::string& text) {
  try {
    build(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(MaterialTransmission, OpaqueByDefault) {
  const Material m = build(R"({"alpha": 0.1, "f0": 0.04})");
  EXPECT_FALSE(isTransmissive(m));
  EXPECT_EQ(m.fresnel, rules::f64::F_SCHLICK);
  EXPECT_TRUE(std::isinf(m.attenuationDistance));
  EXPECT_FALSE(toJson(m).contains("transmission"));
}

TEST(MaterialTransmission, TransmissionTakesTheExactDielectric) {
  const Material m = build(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_color": [0.5, 0.8, 1],
                               "attenuation_distance": 2})");
  EXPECT_EQ(m.fresnel, rules::f64::F_DIELECTRIC);
  EXPECT_EQ(m.eta, glm::dvec3(1.5));
  const rules::f64::TransmissionParams t = transmissionParams64(m);
  EXPECT_EQ(t.ior, 1.5);
  EXPECT_NEAR(t.sigma.x, -std::log(0.5) / 2, 1e-15);
  EXPECT_EQ(t.sigma.z, 0.0);
  const Material again = build(toJson(m).dump());
  EXPECT_EQ(again.transmission, 1.0);
  EXPECT_EQ(again.attenuationColor, m.attenuationColor);
  EXPECT_EQ(again.attenuationDistance, 2.0);
  const Material thin = build(R"({"alpha": 0, "ior": 1.5, "transmission": 0.5, "thin_walled": true,
                                  "thickness": 0.01, "diffuse": 0.5})");
  EXPECT_TRUE(thin.thinWalled);
  EXPECT_EQ(build(toJson(thin).dump()).thickness, 0.01);
}

TEST(MaterialTransmission, TransparentPresetsKeepTheirF0) {
  for (const char* name : {"water", "plastic-glass-low", "glass-high-ruby", "diamond"}) {
    const Material m = build(std::string(R"({"roughness": 0, "preset": ")") + name + "\"}");
    const Preset& preset = *findPreset(name);
    EXPECT_TRUE(isTransmissive(m)) << name;
    EXPECT_EQ(m.fresnel, rules::f64::F_DIELECTRIC) << name;
    EXPECT_NEAR(rules::f64::fresnel_dielectric(m.eta.x, 1.0), preset.f0_linear.x, 1e-12) << name;
    // transmission 0 keeps the course's opaque insulator, bit for bit.
    const Material opaque = build(std::string(R"({"roughness": 0, "transmission": 0, "preset": ")") + name + "\"}");
    EXPECT_EQ(opaque.fresnel, rules::f64::F_SCHLICK);
    EXPECT_EQ(opaque.f0, preset.f0_linear);
  }
  EXPECT_LT(build(R"({"roughness": 0, "preset": "glass-high-ruby"})").attenuationColor.y, 0.5);
  for (const char* name : {"gold", "plastic-high"})
    EXPECT_FALSE(isTransmissive(build(std::string(R"({"roughness": 0, "preset": ")") + name + "\"}"))) << name;
}

TEST(MaterialTransmission, BadInputsNameTheField) {
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1.5})"),
            "glass.json: field 'transmission': must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 0.8, "transmission": 1})"),
            "glass.json: field 'ior': a transmissive material's index of refraction (inside over outside) must be >= "
            "1, got 0.8");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": [1.5, 1.5, 1.6], "transmission": 1})"),
            "glass.json: field 'ior': a transmissive material has one index of refraction (no dispersion), got "
            "1.5,1.5,1.6");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_distance": 0})"),
            "glass.json: field 'attenuation_distance': must be > 0 (leave it out for no absorption), got 0");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_distance": -1})"),
            "glass.json: field 'attenuation_distance': must be > 0 (leave it out for no absorption), got -1");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_color": [0.5, 2, 0.5]})"),
            "glass.json: field 'attenuation_color': every component must be in [0, 1], got 0.5,2,0.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "f0": 0.04, "attenuation_distance": 1})"),
            "glass.json: field 'attenuation_distance': is only used by a transmissive material (transmission > 0)");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "thickness": 1})"),
            "glass.json: field 'thickness': is only used by a thin-walled material (thin_walled true)");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "f0": 0.04, "fresnel": "schlick", "transmission": 1})"),
            "glass.json: field 'fresnel': a transmissive material (transmission > 0) takes fresnel 'dielectric', not "
            "'schlick'");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "distribution": "beckmann", "transmission": 1})"),
            "glass.json: field 'distribution': a transmissive material samples GGX's visible normals: must be 'ggx'");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "thin_walled": 1})"),
            "glass.json: field 'thin_walled': expected true or false");
  // NaN cannot be written in JSON; through the spec (as the API gives it) it is refused alike.
  MaterialSpec spec;
  spec.alpha = 0;
  spec.ior = glm::dvec3(1.5);
  spec.transmission = 1;
  spec.attenuationDistance = std::nan("");
  try {
    buildMaterial(spec, [](std::string_view field) { return "api." + std::string(field); });
    ADD_FAILURE() << "NaN accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "api.attenuation_distance: must be > 0 (leave it out for no absorption), got nan");
  }
}

}  // namespace
}  // namespace facet::materials
