// The JSON material format: what it accepts and how it reports errors, its
// transmission fields included.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
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
                .rfind("test.json: field 'ior': every component must be in (0, 1000], got 1.5,0,1.5", 0),
            0u);
}

// The Fresnel terms raise an index to the fourth power in float: past
// kMaxOpticalConstant that overflows, so no material may hold a larger one,
// however it is given.
TEST(MaterialFile, IndicesOfRefractionAreBoundedWhereverTheyComeFrom) {
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "fresnel": "dielectric", "ior": 2e19})"),
            "test.json: field 'ior': every component must be in (0, 1000], got 2e+19,2e+19,2e+19");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "fresnel": "conductor", "eta": [0.2, 1e10, 0.2], "k": 3})"),
            "test.json: field 'eta': every component must be in (0, 1000], got 0.2,1e+10,0.2");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "fresnel": "conductor", "eta": 0.2, "k": [3, 3, 1e308]})"),
            "test.json: field 'k': every component must be in [0, 1000], got 3,3,1e+308");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "fresnel": "dielectric", "f0": 0.999})")
                .rfind("test.json: field 'f0': gives an index of refraction of 3998, above the largest, 1000", 0),
            0u);
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "transmission": 1, "ior": 1001})"),
            "test.json: field 'ior': every component must be in (0, 1000], got 1001,1001,1001");
  const Material glass = build(R"({"alpha": 0.1, "transmission": 1, "ior": 1000})");
  EXPECT_EQ(glass.eta, glm::dvec3(kMaxOpticalConstant));
  const Material metal = build(R"({"alpha": 0.1, "fresnel": "conductor", "eta": 1000, "k": [0, 1000, 1]})");
  EXPECT_EQ(metal.k, glm::dvec3(0, kMaxOpticalConstant, 1));
}

TEST(MaterialFile, LoadNamesTheFileOnSyntaxErrors) {
  try {
    loadMaterial("/nonexistent/material.json");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/material.json: cannot open material file");
  }
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
            "test.json: field 'transmission': must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 0.8, "transmission": 1})"),
            "test.json: field 'ior': a transmissive material's index of refraction (inside over outside) must be >= "
            "1, got 0.8");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": [1.5, 1.5, 1.6], "transmission": 1})"),
            "test.json: field 'ior': a transmissive material has one index of refraction (no dispersion), got "
            "1.5,1.5,1.6");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_distance": 0})"),
            "test.json: field 'attenuation_distance': must be > 0 (leave it out for no absorption), got 0");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_distance": -1})"),
            "test.json: field 'attenuation_distance': must be > 0 (leave it out for no absorption), got -1");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "attenuation_color": [0.5, 2, 0.5]})"),
            "test.json: field 'attenuation_color': every component must be in [0, 1], got 0.5,2,0.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "f0": 0.04, "attenuation_distance": 1})"),
            "test.json: field 'attenuation_distance': is only used by a transmissive material (transmission > 0)");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "thickness": 1})"),
            "test.json: field 'thickness': is only used by a thin-walled material (thin_walled true)");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "f0": 0.04, "fresnel": "schlick", "transmission": 1})"),
            "test.json: field 'fresnel': a transmissive material (transmission > 0) takes fresnel 'dielectric', not "
            "'schlick'");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "distribution": "beckmann", "transmission": 1})"),
            "test.json: field 'distribution': a transmissive material samples GGX's visible normals: must be 'ggx'");
  EXPECT_EQ(errorOf(R"({"alpha": 0, "ior": 1.5, "transmission": 1, "thin_walled": 1})"),
            "test.json: field 'thin_walled': expected true or false");
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

TEST(MaterialAnisotropy, IsotropicByDefaultReadAndRoundTrips) {
  EXPECT_EQ(build(R"({"alpha": 0.1})").anisotropy, 0.0);
  const Material m =
      build(R"({"preset": "aluminum", "roughness": 0.3, "anisotropy": 0.6, "anisotropy_rotation": 0.5})");
  EXPECT_EQ(m.anisotropy, 0.6);
  EXPECT_EQ(m.anisotropyRotation, 0.5);
  const Material again = build(toJson(m).dump());
  EXPECT_EQ(again.anisotropy, 0.6);
  EXPECT_EQ(again.anisotropyRotation, 0.5);
  const rules::f64::BrdfParams p = toParams64(m);
  EXPECT_EQ(p.anisotropy, 0.6);
  EXPECT_NEAR(p.tangent.x, std::cos(0.5), 1e-15);
  EXPECT_NEAR(p.tangent.y, std::sin(0.5), 1e-15);
}

TEST(MaterialAnisotropy, BadInputsNameTheField) {
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "anisotropy": 1.5})"),
            "test.json: field 'anisotropy': must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "anisotropy": -0.2})"),
            "test.json: field 'anisotropy': must be in [0, 1], got -0.2");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "anisotropy": "strong"})"), "test.json: field 'anisotropy': expected a number");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "anisotropy_rotation": 1})"),
            "test.json: field 'anisotropy_rotation': is only used with anisotropy (give anisotropy too)");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "distribution": "blinn-phong", "anisotropy": 0.5})"),
            "test.json: field 'anisotropy': needs distribution 'ggx' or 'beckmann' (Blinn-Phong has no anisotropic "
            "form here)");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "ior": 1.5, "transmission": 1, "anisotropy": 0.5})"),
            "test.json: field 'anisotropy': is not defined for a transmissive material (transmission > 0)");
  MaterialSpec spec;
  spec.alpha = 0.1;
  for (double bad : {std::nan(""), HUGE_VAL}) {
    spec.anisotropy = 0.5;
    spec.anisotropyRotation = bad;
    EXPECT_THROW(buildMaterial(spec, [](std::string_view field) { return std::string(field); }), std::invalid_argument);
    spec.anisotropy = bad;
    spec.anisotropyRotation.reset();
    EXPECT_THROW(buildMaterial(spec, [](std::string_view field) { return std::string(field); }), std::invalid_argument);
  }
}

TEST(MaterialClearcoat, UncoatedByDefaultReadAndRoundTrips) {
  EXPECT_EQ(build(R"({"alpha": 0.1})").clearcoat, 0.0);
  const Material m = build(R"({"alpha": 0.2, "diffuse": 0.5, "clearcoat": 0.8, "clearcoat_roughness": 0.3})");
  EXPECT_EQ(m.clearcoat, 0.8);
  EXPECT_EQ(m.clearcoatRoughness, 0.3);
  const Material again = build(toJson(m).dump());
  EXPECT_EQ(again.clearcoat, 0.8);
  EXPECT_EQ(again.clearcoatRoughness, 0.3);
  const rules::f64::BrdfParams p = toParams64(m);
  EXPECT_EQ(p.clearcoat, 0.8);
  EXPECT_NEAR(p.clearcoat_alpha, 0.09, 1e-15);  // alpha = roughness^2
  EXPECT_EQ(p.clearcoat_normal, glm::dvec3(0, 0, 1));
}

TEST(MaterialClearcoat, BadInputsNameTheField) {
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "clearcoat": 1.5})"), "test.json: field 'clearcoat': must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "clearcoat": 1, "clearcoat_roughness": -0.2})"),
            "test.json: field 'clearcoat_roughness': must be in [0, 1], got -0.2");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "clearcoat": "thick"})"), "test.json: field 'clearcoat': expected a number");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "clearcoat_roughness": 0.1})"),
            "test.json: field 'clearcoat_roughness': is only used with clearcoat (give clearcoat too)");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "ior": 1.5, "transmission": 1, "clearcoat": 0.5})"),
            "test.json: field 'clearcoat': is not defined for a transmissive material (transmission > 0)");
  MaterialSpec spec;
  spec.alpha = 0.1;
  spec.clearcoat = std::nan("");
  EXPECT_THROW(buildMaterial(spec, [](std::string_view field) { return std::string(field); }), std::invalid_argument);
}

TEST(MaterialSheen, NoSheenByDefaultReadAndRoundTrips) {
  EXPECT_EQ(build(R"({"alpha": 0.1})").sheenColor, glm::dvec3(0.0));
  const Material m = build(R"({"alpha": 0.2, "diffuse": 0.5, "sheen_color": [0.6, 0.3, 0.1], "sheen_roughness": 0.4})");
  EXPECT_EQ(m.sheenColor, glm::dvec3(0.6, 0.3, 0.1));
  EXPECT_EQ(m.sheenRoughness, 0.4);
  const Material again = build(toJson(m).dump());
  EXPECT_EQ(again.sheenColor, m.sheenColor);
  EXPECT_EQ(again.sheenRoughness, 0.4);
  const rules::f64::BrdfParams p = toParams64(m);
  EXPECT_EQ(p.sheen_color, m.sheenColor);
  EXPECT_NEAR(p.sheen_alpha, 0.16, 1e-15);  // alpha = roughness^2
  // The albedo's knots fall from grazing to head-on (a rough sheen's E).
  EXPECT_GT(p.sheen_albedo_near.x, p.sheen_albedo_far.w);
  EXPECT_GT(p.sheen_albedo_far.w, 0.0);
}

TEST(MaterialSheen, BadInputsNameTheField) {
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "sheen_color": [0.5, 1.5, 0.5]})"),
            "test.json: field 'sheen_color': each channel must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "sheen_color": 1, "sheen_roughness": 2})"),
            "test.json: field 'sheen_roughness': must be in [0, 1], got 2");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "sheen_color": "red"})"),
            "test.json: field 'sheen_color': expected a number or an array of 3 numbers (r, g, b)");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "sheen_roughness": 0.1})"),
            "test.json: field 'sheen_roughness': is only used with sheen_color (give sheen_color too)");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "ior": 1.5, "transmission": 1, "sheen_color": 0.5})"),
            "test.json: field 'sheen_color': is not defined for a transmissive material (transmission > 0)");
  MaterialSpec spec;
  spec.alpha = 0.1;
  spec.sheenColor = glm::dvec3(std::nan(""));
  EXPECT_THROW(buildMaterial(spec, [](std::string_view field) { return std::string(field); }), std::invalid_argument);
}

TEST(MaterialIridescence, NoFilmByDefaultReadAndRoundTrips) {
  EXPECT_EQ(build(R"({"alpha": 0.1})").iridescence, 0.0);
  const Material m = build(
      R"({"preset": "gold", "alpha": 0.1, "iridescence": 0.8, "iridescence_ior": 1.5, "iridescence_thickness": 250})");
  EXPECT_EQ(m.iridescence, 0.8);
  EXPECT_EQ(m.iridescenceIor, 1.5);
  EXPECT_EQ(m.iridescenceThickness, 250.0);
  const Material again = build(toJson(m).dump());
  EXPECT_EQ(again.iridescence, 0.8);
  EXPECT_EQ(again.iridescenceIor, 1.5);
  EXPECT_EQ(again.iridescenceThickness, 250.0);
  const rules::f64::BrdfParams p = toParams64(m);
  EXPECT_EQ(p.iridescence, 0.8);
  EXPECT_EQ(p.iridescence_ior, 1.5);
  EXPECT_EQ(p.iridescence_thickness, 250.0);
  // The extension's defaults: index 1.3, 400 nm.
  const Material defaults = build(R"({"alpha": 0.1, "f0": 0.04, "iridescence": 1})");
  EXPECT_EQ(defaults.iridescenceIor, 1.3);
  EXPECT_EQ(defaults.iridescenceThickness, 400.0);
}

TEST(MaterialIridescence, BadInputsNameTheField) {
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "iridescence": 1.5})"),
            "test.json: field 'iridescence': must be in [0, 1], got 1.5");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "iridescence": 1, "iridescence_ior": 0})"),
            "test.json: field 'iridescence_ior': must be in [1, 1000] (the extension's minimum is 1), got 0");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "iridescence": 1, "iridescence_thickness": -5})"),
            "test.json: field 'iridescence_thickness': must be finite and >= 0 (nanometres), got -5");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "iridescence_thickness": 300})"),
            "test.json: field 'iridescence_thickness': is only used with iridescence (give iridescence too)");
  EXPECT_EQ(errorOf(R"({"alpha": 0.1, "ior": 1.5, "transmission": 1, "iridescence": 0.5})"),
            "test.json: field 'iridescence': is not defined for a transmissive material (transmission > 0)");
}

TEST(MaterialMetallicRoughness, BaseColorAndMetallicGiveDiffuseAndF0AsGltfDoes) {
  const Material plastic = build(R"({"base_color": [0.8, 0.1, 0.1], "metallic": 0, "roughness": 0.4})");
  EXPECT_EQ(plastic.fresnel, rules::f64::F_SCHLICK);
  EXPECT_EQ(plastic.diffuse, glm::dvec3(0.8, 0.1, 0.1));
  EXPECT_EQ(plastic.f0, glm::dvec3(0.04));
  const Material metal = build(R"({"base_color": [0.9, 0.6, 0.2], "metallic": 1, "roughness": 0.3})");
  EXPECT_EQ(metal.diffuse, glm::dvec3(0.0));
  EXPECT_EQ(metal.f0, glm::dvec3(0.9, 0.6, 0.2));
  const Material half = build(R"({"base_color": 0.5, "metallic": 0.5, "roughness": 0.3})");
  EXPECT_NEAR(half.diffuse.g, 0.25, 1e-15);
  EXPECT_NEAR(half.f0.g, 0.27, 1e-15);
  // The other layers combine with them; a round trip keeps the resolved terms.
  const Material coated = build(R"({"base_color": 0.5, "metallic": 0, "roughness": 0.5, "clearcoat": 1})");
  EXPECT_EQ(coated.clearcoat, 1.0);
  const Material again = build(toJson(coated).dump());
  EXPECT_EQ(again.diffuse, coated.diffuse);
  EXPECT_EQ(again.f0, coated.f0);
}

TEST(MaterialMetallicRoughness, BadInputsNameTheField) {
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "roughness": 0.5})"),
            "test.json: field 'metallic': base_color and metallic are given together (glTF's default metallic of 1 "
            "would make any colour a metal)");
  EXPECT_EQ(errorOf(R"({"metallic": 1, "roughness": 0.5})").substr(0, 31), "test.json: field 'base_color': ");
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "metallic": 0, "diffuse": 0.5, "roughness": 0.5})"),
            "test.json: field 'diffuse': is not combined with base_color and metallic, which give c_diff and F(0)");
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "metallic": 0, "preset": "gold", "roughness": 0.5})"),
            "test.json: field 'preset': is not combined with base_color and metallic, which give c_diff and F(0)");
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "metallic": 0, "transmission": 1, "roughness": 0.5})"),
            "test.json: field 'transmission': is not combined with base_color and metallic, which give c_diff and "
            "F(0)");
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "metallic": 0, "fresnel": "dielectric", "roughness": 0.5})"),
            "test.json: field 'fresnel': must be 'schlick' with base_color and metallic (glTF's Fresnel), got "
            "'dielectric'");
  EXPECT_EQ(errorOf(R"({"base_color": [0.5, 1.2, 0.5], "metallic": 0, "roughness": 0.5})"),
            "test.json: field 'base_color': each channel must be in [0, 1], got 1.2");
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "metallic": -0.5, "roughness": 0.5})"),
            "test.json: field 'metallic': must be in [0, 1], got -0.5");
  EXPECT_EQ(errorOf(R"({"base_color": 0.5, "metallic": "yes", "roughness": 0.5})"),
            "test.json: field 'metallic': expected a number");
  MaterialSpec spec;
  spec.roughness = 0.5;
  spec.baseColor = glm::dvec3(std::nan(""));
  spec.metallic = 0.0;
  EXPECT_THROW(buildMaterial(spec, [](std::string_view field) { return std::string(field); }), std::invalid_argument);
}

}  // namespace
}  // namespace facet::materials
