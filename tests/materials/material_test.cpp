// The JSON material format: what it accepts and how it reports errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "materials/material.h"
#include "materials/presets.h"

namespace facet::materials {
namespace {

Material build(const std::string& text) {
  const std::string source = "test.json";
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

TEST(MaterialFile, PresetWithRoughness) {
  Material m = build(R"({"preset": "gold", "roughness": 0.5, "geometry": "smith-ggx"})");
  EXPECT_EQ(m.name, "gold");
  EXPECT_EQ(m.distribution, rules::f64::D_GGX);
  EXPECT_EQ(m.geometry, rules::f64::G_SMITH_GGX);
  EXPECT_EQ(m.fresnel, rules::f64::F_SCHLICK);
  EXPECT_DOUBLE_EQ(m.alpha, 0.25);  // alpha = roughness^2
  EXPECT_EQ(m.f0, findPreset("gold")->f0_linear);
  EXPECT_EQ(m.diffuse, glm::dvec3(0));
}

TEST(MaterialFile, DielectricIorFromPreset) {
  Material m = build(R"({"preset": "water", "fresnel": "dielectric", "alpha": 0.1})");
  EXPECT_NEAR(m.eta.x, 1.33, 0.005);
}

TEST(MaterialFile, ConductorAndRoundTrip) {
  Material m = build(R"({"name": "cu", "distribution": "beckmann", "fresnel": "conductor",
                         "alpha": 0.2, "eta": [0.27, 0.68, 1.22], "k": [3.61, 2.63, 2.29],
                         "diffuse": 0})");
  EXPECT_EQ(m.fresnel, rules::f64::F_CONDUCTOR);
  EXPECT_EQ(m.k, glm::dvec3(3.61, 2.63, 2.29));
  Material again = build(toJson(m).dump());
  EXPECT_EQ(again.eta, m.eta);
  EXPECT_EQ(again.k, m.k);
  EXPECT_EQ(again.distribution, m.distribution);
  EXPECT_EQ(again.alpha, m.alpha);
}

TEST(MaterialFile, BlenderMetallicReadsF0AndRoundTrips) {
  Material m = build(R"({"preset": "gold", "fresnel": "blender-metallic", "roughness": 0.5})");
  EXPECT_EQ(m.fresnel, rules::f64::F_BLENDER_METALLIC);
  EXPECT_EQ(m.f0, findPreset("gold")->f0_linear);
  Material again = build(toJson(m).dump());
  EXPECT_EQ(again.fresnel, m.fresnel);
  EXPECT_EQ(again.f0, m.f0);
  EXPECT_EQ(errorOf(R"({"fresnel": "blender-metallic", "alpha": 0.2})"),
            "test.json: field 'f0': required by fresnel 'blender-metallic' (or give a preset)");
}

TEST(MaterialFile, EnergyCompensationIsOffByDefaultAndRoundTrips) {
  EXPECT_FALSE(build(R"({"preset": "gold", "roughness": 0.5})").energyCompensation);
  Material m = build(R"({"preset": "gold", "roughness": 0.5, "energy_compensation": true})");
  EXPECT_TRUE(m.energyCompensation);
  EXPECT_TRUE(build(toJson(m).dump()).energyCompensation);
  EXPECT_EQ(errorOf(R"({"preset": "gold", "alpha": 0.2, "energy_compensation": 1})"),
            "test.json: field 'energy_compensation': expected true or false");
}

TEST(MaterialFile, ErrorsNameTheFileTheFieldAndTheRule) {
  EXPECT_EQ(errorOf(R"({"alpha": 1.5, "f0": 0.04})"), "test.json: field 'alpha': must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0.5, "f0": [0.04, 2, 0.04]})"),
            "test.json: field 'f0': every component must be in [0, 1], got 0.04,2,0.04");
  EXPECT_EQ(errorOf(R"({"alpha": 0.5, "colour": 1})").rfind("test.json: field 'colour': unknown field", 0), 0u);
  EXPECT_EQ(errorOf(R"({"alpha": 0.5, "distribution": "phong"})"),
            "test.json: field 'distribution': unknown distribution 'phong' (expected one of: ggx, "
            "beckmann, blinn-phong)");
  EXPECT_EQ(errorOf(R"({"alpha": "rough"})"), "test.json: field 'alpha': expected a number");
  EXPECT_EQ(errorOf(R"({"f0": 0.04})"), "test.json: field 'alpha': required (or roughness = sqrt(alpha))");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "fresnel": "conductor", "eta": 1})"),
            "test.json: field 'k': required by fresnel 'conductor'");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "k": 1})"),
            "test.json: field 'k': is only used by fresnel 'conductor', not 'schlick'");
  EXPECT_EQ(
      errorOf(R"({"alpha": 0.1, "preset": "mithril"})").rfind("test.json: field 'preset': unknown preset 'mithril'", 0),
      0u);
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "fresnel": "dielectric", "ior": [1.5, 0, 1.5]})")
                .rfind("test.json: field 'ior': every component must be finite and > 0, got 1.5,0,1.5", 0),
            0u);
}

TEST(MaterialFile, LoadNamesTheFileOnSyntaxErrors) {
  try {
    loadMaterial("/nonexistent/material.json");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/material.json: cannot open material file");
  }
}

}  // namespace
}  // namespace facet::materials
