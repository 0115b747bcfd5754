// glTF material extensions facet reads beyond those of transmission
// (gltf_transmission_test.cpp): KHR_materials_emissive_strength,
// KHR_materials_specular, KHR_materials_clearcoat, KHR_materials_sheen,
// KHR_materials_anisotropy and KHR_materials_unlit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/cpu/reference_renderer.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

namespace facet::scene {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::ThrowsMessage;

class GltfMaterialExtensions : public facet::testing::TempDirTest {
 protected:
  // The textured quad of one black dielectric, double-sided, with `members` added.
  // The file has one texture, a grey 2 x 2 PNG, for the slots that name it;
  // with `secondTexcoords` the quad has TEXCOORD_1 too (TEXCOORD_0's values).
  std::filesystem::path write(const std::string& name, const nlohmann::json& members, bool secondTexcoords = false) {
    nlohmann::json m = {{"doubleSided", true},
                        {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0.0}}}};
    m.update(members);
    facet::testing::writePng(dir_ / "grey.png", 2, 2, std::vector<facet::testing::Rgba8>(4, {128, 128, 128, 255}));
    nlohmann::json parts = {{"materials", {m}}, {"textures", {{{"source", 0}}}}, {"images", {{{"uri", "grey.png"}}}}};
    if (secondTexcoords)
      parts["meshes"] = {{{"primitives",
                           {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 1}}},
                             {"indices", 2},
                             {"material", 0}}}}}};
    return facet::testing::writeTexturedQuad(dir_, name, parts);
  }
  static nlohmann::json strength(double s) { return {{"KHR_materials_emissive_strength", {{"emissiveStrength", s}}}}; }
};

TEST_F(GltfMaterialExtensions, EmissiveStrengthScalesTheFactorPastOne) {
  const Scene scene = loadScene(write("strong", {{"emissiveFactor", {1.0, 0.5, 0.25}}, {"extensions", strength(4.0)}}));
  EXPECT_EQ(scene.materials.at(0).emission, glm::dvec3(4.0, 2.0, 1.0));
  EXPECT_THAT(scene.warnings, IsEmpty());
  // Without the extension the factor is the emission.
  EXPECT_EQ(loadScene(write("plain", {{"emissiveFactor", {1.0, 0.5, 0.25}}})).materials.at(0).emission,
            glm::dvec3(1.0, 0.5, 0.25));
}

TEST_F(GltfMaterialExtensions, AStrongEmitterRendersBrighterThanWhite) {
  Scene scene = loadScene(write("render", {{"emissiveFactor", {1.0, 1.0, 1.0}}, {"extensions", strength(5.0)}}));
  scene.render.width = scene.render.height = 8;
  scene.camera = {{0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 20.0};
  const Image image = cpu::renderReference(scene, buildGeometry(scene));
  const glm::vec4 centre = image.beauty[std::size_t(4 * 8 + 4)];
  // 5 emitted, plus what the black dielectric's 4% reflects of the studio environment.
  EXPECT_GE(centre.g, 5.0f);
  EXPECT_LT(centre.g, 5.5f);
}

TEST_F(GltfMaterialExtensions, EmissiveStrengthIsHeldToTheRulesOfRadiance) {
  const auto fails = [&](const std::string& name, double s, const std::string& message) {
    const std::filesystem::path file = write(name, {{"emissiveFactor", {1.0, 1.0, 1.0}}, {"extensions", strength(s)}});
    EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(message))) << name;
  };
  fails("negative", -1.0,
        "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength: must be >= 0, is -1");
  fails("huge", 1e31,
        "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength: emissiveFactor times "
        "emissiveStrength must be at most 1e30");
}

// The specification's dielectric_f0 = min(F(0) of the index x specularColorFactor, 1) x specularFactor.
TEST_F(GltfMaterialExtensions, SpecularScalesAndTintsTheDielectricsF0) {
  const auto f0 = [&](const std::string& name, const nlohmann::json& extensions, double metallic = 0.0) {
    nlohmann::json members = {{"extensions", extensions}};
    members["pbrMetallicRoughness"] = {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", metallic}};
    return loadScene(write(name, members)).materials.at(0).f0;
  };
  const nlohmann::json tint = {{"specularColorFactor", {2.0, 1.0, 0.5}}};
  const glm::dvec3 tinted = f0("tint", {{"KHR_materials_specular", tint}});
  EXPECT_NEAR(tinted.r, 0.08, 1e-15);
  EXPECT_NEAR(tinted.g, 0.04, 1e-15);
  EXPECT_NEAR(tinted.b, 0.02, 1e-15);
  // ior 3: F(0) 0.25, x 5 capped at 1, then x specularFactor.
  const nlohmann::json strong = {{"specularColorFactor", {5.0, 1.0, 1.0}}, {"specularFactor", 0.5}};
  const glm::dvec3 capped = f0("capped", {{"KHR_materials_ior", {{"ior", 3.0}}}, {"KHR_materials_specular", strong}});
  EXPECT_NEAR(capped.r, 0.5, 1e-15);
  EXPECT_NEAR(capped.g, 0.125, 1e-15);
  // A metal's F(0) is its base colour whatever the dielectric's.
  EXPECT_EQ(f0("metal", {{"KHR_materials_specular", tint}}, 1.0), glm::dvec3(0.5));
}

TEST_F(GltfMaterialExtensions, WhatSpecularCannotDoIsAWarning) {
  const nlohmann::json half = {
      {"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularTexture", {{"index", 0}}}}}};
  EXPECT_THAT(loadScene(write("half", {{"extensions", half}})).warnings,
              ElementsAre(HasSubstr("KHR_materials_specular.specularFactor: below 1 scales F(0) only; F(90) stays 1")));
  nlohmann::json glass = {{"KHR_materials_specular", {{"specularFactor", 1.0}}},
                          {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}};
  EXPECT_THAT(loadScene(write("glass", {{"extensions", glass}})).warnings,
              ElementsAre(HasSubstr("materials[0].extensions.KHR_materials_specular: is not applied to a transmissive "
                                    "material")));
}

// On a textured material the factors and the two textures give F(0) per hit:
// the material keeps F(0) of the index times the colour factor, and the
// factor, beside its slots.
TEST_F(GltfMaterialExtensions, SpecularTexturesAndTheIndexShadeATexturedMaterial) {
  nlohmann::json members = {{"extensions",
                             {{"KHR_materials_ior", {{"ior", 2.0}}},
                              {"KHR_materials_specular",
                               {{"specularFactor", 1.0},
                                {"specularColorFactor", {1.0, 0.5, 2.0}},
                                {"specularTexture", {{"index", 0}}},
                                {"specularColorTexture", {{"index", 0}}}}}}}};
  members["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}};
  const Scene scene = loadScene(write("textured", members));
  EXPECT_THAT(scene.warnings, IsEmpty());
  const materials::Material& m = scene.materials.at(0);
  ASSERT_TRUE(m.textures.has_value());
  EXPECT_NEAR(m.textures->specularColor.r, 1.0 / 9.0, 1e-15);
  EXPECT_NEAR(m.textures->specularColor.g, 0.5 / 9.0, 1e-15);
  EXPECT_NEAR(m.textures->specularColor.b, 2.0 / 9.0, 1e-15);
  EXPECT_EQ(m.textures->specular, 1.0);
  EXPECT_GE(m.textures->specularTexture.texture, 0);
  EXPECT_GE(m.textures->specularColorTexture.texture, 0);
}

TEST_F(GltfMaterialExtensions, SpecularFactorsAreChecked) {
  const auto fails = [&](const std::string& name, const nlohmann::json& specular, const std::string& message) {
    const std::filesystem::path file = write(name, {{"extensions", {{"KHR_materials_specular", specular}}}});
    EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(message))) << name;
  };
  fails("factor", {{"specularFactor", 2.0}}, "KHR_materials_specular.specularFactor: must be in [0, 1], is 2");
  fails("colour", {{"specularColorFactor", {1.0, -1.0, 1.0}}},
        "KHR_materials_specular.specularColorFactor: every component must be a finite number >= 0");
}

TEST_F(GltfMaterialExtensions, ClearcoatFactorsAndTexturesAreRead) {
  const nlohmann::json coat = {{"clearcoatFactor", 0.75}, {"clearcoatRoughnessFactor", 0.2}};
  const Scene scene = loadScene(write("coat", {{"extensions", {{"KHR_materials_clearcoat", coat}}}}));
  EXPECT_EQ(scene.materials.at(0).clearcoat, 0.75);
  EXPECT_EQ(scene.materials.at(0).clearcoatRoughness, 0.2);
  EXPECT_THAT(scene.warnings, IsEmpty());
  EXPECT_FALSE(scene.materials.at(0).textures.has_value());
  // Without the extension there is no coat; its textures are read, on
  // either set, with the normal map's scale, and make the material textured.
  EXPECT_EQ(loadScene(write("bare", nlohmann::json::object())).materials.at(0).clearcoat, 0.0);
  nlohmann::json textured = coat;
  textured["clearcoatTexture"] = {{"index", 0}};
  textured["clearcoatRoughnessTexture"] = {{"index", 0}, {"texCoord", 1}};
  textured["clearcoatNormalTexture"] = {{"index", 0}, {"scale", 0.5}};
  const Scene read = loadScene(write("textured", {{"extensions", {{"KHR_materials_clearcoat", textured}}}}, true));
  EXPECT_EQ(read.materials.at(0).clearcoat, 0.75);
  EXPECT_THAT(read.warnings, IsEmpty());
  ASSERT_TRUE(read.materials.at(0).textures.has_value());
  const materials::MaterialTextures& t = *read.materials.at(0).textures;
  EXPECT_EQ(t.clearcoatTexture.texture, 0);
  EXPECT_EQ(t.clearcoatRoughnessTexture.texCoord, 1);
  EXPECT_EQ(t.clearcoatNormalTexture.texture, 0);
  EXPECT_EQ(t.clearcoatNormalScale, 0.5);
  EXPECT_EQ(t.baseColorTexture.texture, -1);
  // A texture info that is not one is an error naming it.
  for (const auto& [name, info, field] :
       {std::tuple{"far", nlohmann::json{{"index", 3}}, "clearcoatTexture.index"},
        std::tuple{"noindex", nlohmann::json{{"texCoord", 0}}, "clearcoatTexture.index: is required"},
        std::tuple{"set", nlohmann::json{{"index", 0}, {"texCoord", -1}}, "clearcoatTexture.texCoord"},
        std::tuple{"word", nlohmann::json("coat.png"), "clearcoatTexture: must be a texture info object"}}) {
    const std::filesystem::path file = write(
        name, {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}, {"clearcoatTexture", info}}}}}});
    EXPECT_THAT([&] { loadScene(file); }, ThrowsMessage<InputError>(HasSubstr(field))) << name;
  }
  const std::filesystem::path bad =
      write("bad", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.5}}}}}});
  EXPECT_THAT([&] { loadScene(bad); }, ThrowsMessage<InputError>(HasSubstr("KHR_materials_clearcoat.clearcoatFactor")));
}

TEST_F(GltfMaterialExtensions, AClearCoatLiesOverTheEmission) {
  // Seen head-on, a full coat keeps 1 - F(1) = 0.96 of the emission under it
  // (KHR_materials_clearcoat, "Emission"), and reflects its own 4%.
  auto centre = [&](const std::string& name, const nlohmann::json& extensions) {
    Scene scene = loadScene(write(name, {{"emissiveFactor", {1.0, 1.0, 1.0}}, {"extensions", extensions}}));
    scene.render.width = scene.render.height = 8;
    scene.camera = {{0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 20.0};
    return cpu::renderReference(scene, buildGeometry(scene)).beauty[std::size_t(4 * 8 + 4)];
  };
  nlohmann::json coated = strength(5.0);
  coated["KHR_materials_clearcoat"] = {{"clearcoatFactor", 1.0}};
  const glm::vec4 bare = centre("bare", strength(5.0)), coat = centre("coated", coated);
  EXPECT_LT(coat.g, bare.g);
  EXPECT_GT(coat.g, 0.96f * 5.0f);
  EXPECT_LT(coat.g, 0.96f * 5.0f + 0.5f);
}

TEST_F(GltfMaterialExtensions, SheenFactorsAndTexturesAreRead) {
  const nlohmann::json sheen = {{"sheenColorFactor", {0.6, 0.2, 0.1}}, {"sheenRoughnessFactor", 0.4}};
  const Scene scene = loadScene(write("sheen", {{"extensions", {{"KHR_materials_sheen", sheen}}}}));
  EXPECT_EQ(scene.materials.at(0).sheenColor, glm::dvec3(0.6, 0.2, 0.1));
  EXPECT_EQ(scene.materials.at(0).sheenRoughness, 0.4);
  EXPECT_THAT(scene.warnings, IsEmpty());
  // Without the extension there is no sheen.
  EXPECT_EQ(loadScene(write("bare", nlohmann::json::object())).materials.at(0).sheenColor, glm::dvec3(0.0));
  nlohmann::json textured = sheen;
  for (const char* slot : {"sheenColorTexture", "sheenRoughnessTexture"}) textured[slot] = {{"index", 0}};
  const Scene read = loadScene(write("textured", {{"extensions", {{"KHR_materials_sheen", textured}}}}));
  EXPECT_THAT(read.warnings, IsEmpty());
  EXPECT_EQ(read.materials.at(0).sheenRoughness, 0.4);
  ASSERT_TRUE(read.materials.at(0).textures.has_value());
  EXPECT_EQ(read.materials.at(0).textures->sheenColorTexture.texture, 0);
  EXPECT_EQ(read.materials.at(0).textures->sheenRoughnessTexture.texture, 1);  // the same image, linear
  EXPECT_EQ(read.materials.at(0).textures->sheenRoughness, 0.4);
  // A sheen of colour 0 (the extension's default) or of roughness 0 has no
  // roughness to vary per hit; its texture infos are still checked.
  for (const auto& [key, zero] : {std::pair{"sheenColorFactor", nlohmann::json{0.0, 0.0, 0.0}},
                                  std::pair{"sheenRoughnessFactor", nlohmann::json(0.0)}}) {
    nlohmann::json flat = textured;
    flat[key] = zero;
    const Scene none = loadScene(write("none", {{"extensions", {{"KHR_materials_sheen", flat}}}}));
    ASSERT_TRUE(none.materials.at(0).textures.has_value()) << key;
    EXPECT_LT(none.materials.at(0).textures->sheenRoughnessTexture.texture, 0) << key;
    flat["sheenRoughnessTexture"] = {{"index", 7}};
    const std::filesystem::path bad = write("bad", {{"extensions", {{"KHR_materials_sheen", flat}}}});
    EXPECT_THAT([&] { loadScene(bad); }, ThrowsMessage<InputError>(HasSubstr("sheenRoughnessTexture"))) << key;
  }
  const std::filesystem::path bad =
      write("bad", {{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {0.5, 1.5, 0.5}}}}}}});
  EXPECT_THAT([&] { loadScene(bad); }, ThrowsMessage<InputError>(HasSubstr("KHR_materials_sheen.sheenColorFactor")));
  const std::filesystem::path rough =
      write("rough", {{"extensions", {{"KHR_materials_sheen", {{"sheenRoughnessFactor", -0.1}}}}}});
  EXPECT_THAT([&] { loadScene(rough); },
              ThrowsMessage<InputError>(HasSubstr("KHR_materials_sheen.sheenRoughnessFactor")));
}

TEST_F(GltfMaterialExtensions, IridescenceFactorsAndTexturesAreRead) {
  const nlohmann::json film = {{"iridescenceFactor", 0.7},
                               {"iridescenceIor", 1.6},
                               {"iridescenceThicknessMinimum", 150.0},
                               {"iridescenceThicknessMaximum", 520.0}};
  const Scene scene = loadScene(write("film", {{"extensions", {{"KHR_materials_iridescence", film}}}}));
  EXPECT_EQ(scene.materials.at(0).iridescence, 0.7);
  EXPECT_EQ(scene.materials.at(0).iridescenceIor, 1.6);
  EXPECT_EQ(scene.materials.at(0).iridescenceThickness, 520.0);  // the maximum, without a thickness texture
  EXPECT_THAT(scene.warnings, IsEmpty());
  EXPECT_EQ(loadScene(write("bare", nlohmann::json::object())).materials.at(0).iridescence, 0.0);
  nlohmann::json textured = film;
  for (const char* slot : {"iridescenceTexture", "iridescenceThicknessTexture"}) textured[slot] = {{"index", 0}};
  const Scene read = loadScene(write("textured", {{"extensions", {{"KHR_materials_iridescence", textured}}}}));
  EXPECT_THAT(read.warnings, IsEmpty());
  const materials::Material& m = read.materials.at(0);
  EXPECT_EQ(m.iridescence, 0.7);
  EXPECT_EQ(m.iridescenceThickness, 520.0);
  ASSERT_TRUE(m.textures.has_value());
  EXPECT_GE(m.textures->iridescenceTexture.texture, 0);
  EXPECT_GE(m.textures->iridescenceThicknessTexture.texture, 0);
  EXPECT_EQ(m.textures->iridescenceThicknessMinimum, 150.0);
  // Without a film (factor 0), or between a minimum and a maximum alike,
  // the thickness is the maximum everywhere.
  for (const auto& [key, value] :
       {std::pair{"iridescenceFactor", 0.0}, std::pair{"iridescenceThicknessMinimum", 520.0}}) {
    nlohmann::json flat = textured;
    flat[key] = value;
    const Scene none = loadScene(write("none", {{"extensions", {{"KHR_materials_iridescence", flat}}}}));
    ASSERT_TRUE(none.materials.at(0).textures.has_value()) << key;
    EXPECT_LT(none.materials.at(0).textures->iridescenceThicknessTexture.texture, 0) << key;
    flat["iridescenceThicknessTexture"] = {{"index", 7}};
    const std::filesystem::path bad = write("bad", {{"extensions", {{"KHR_materials_iridescence", flat}}}});
    EXPECT_THAT([&] { loadScene(bad); }, ThrowsMessage<InputError>(HasSubstr("iridescenceThicknessTexture"))) << key;
  }
  for (const auto& [key, value] : {std::pair{"iridescenceFactor", 1.5}, std::pair{"iridescenceIor", 0.9},
                                   std::pair{"iridescenceThicknessMaximum", -1.0}}) {
    const std::filesystem::path bad = write("bad", {{"extensions", {{"KHR_materials_iridescence", {{key, value}}}}}});
    EXPECT_THAT([&] { loadScene(bad); },
                ThrowsMessage<InputError>(HasSubstr(std::string("KHR_materials_iridescence.") + key)));
  }
}

TEST_F(GltfMaterialExtensions, AnisotropyFactorsAndTextureAreRead) {
  const nlohmann::json anisotropy = {{"anisotropyStrength", 0.7}, {"anisotropyRotation", 0.5}};
  const Scene scene = loadScene(write("brushed", {{"extensions", {{"KHR_materials_anisotropy", anisotropy}}}}));
  EXPECT_EQ(scene.materials.at(0).anisotropy, 0.7);
  EXPECT_EQ(scene.materials.at(0).anisotropyRotation, 0.5);
  EXPECT_THAT(scene.warnings, IsEmpty());
  EXPECT_EQ(loadScene(write("bare", nlohmann::json::object())).materials.at(0).anisotropy, 0.0);
  nlohmann::json textured = anisotropy;
  textured["anisotropyTexture"] = {{"index", 0}};
  const Scene read = loadScene(write("textured", {{"extensions", {{"KHR_materials_anisotropy", textured}}}}));
  EXPECT_EQ(read.materials.at(0).anisotropy, 0.7);
  EXPECT_THAT(read.warnings, IsEmpty());
  ASSERT_TRUE(read.materials.at(0).textures.has_value());
  EXPECT_EQ(read.materials.at(0).textures->anisotropyTexture.texture, 0);
  const std::filesystem::path strong =
      write("strong", {{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 1.5}}}}}});
  EXPECT_THAT([&] { loadScene(strong); },
              ThrowsMessage<InputError>(HasSubstr("KHR_materials_anisotropy.anisotropyStrength")));
  const std::filesystem::path turned =
      write("turned", {{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyRotation", "half"}}}}}});
  EXPECT_THAT([&] { loadScene(turned); },
              ThrowsMessage<InputError>(HasSubstr("KHR_materials_anisotropy.anisotropyRotation: must be a finite")));
  // A transmissive material stays isotropic, with a warning.
  const Scene glass = loadScene(write("glass", {{"extensions",
                                                 {{"KHR_materials_anisotropy", anisotropy},
                                                  {"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}}));
  EXPECT_EQ(glass.materials.at(0).anisotropy, 0.0);
  EXPECT_THAT(glass.warnings, ElementsAre(HasSubstr("is not applied to a transmissive material")));
}

TEST_F(GltfMaterialExtensions, UnlitIsAnEmitterOfTheBaseColourThatReflectsNothing) {
  const nlohmann::json unlit = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.4, 0.2, 1.0}}}},
                                {"emissiveFactor", {1.0, 1.0, 1.0}},
                                {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}};
  const Scene scene = loadScene(write("unlit", unlit));
  const materials::Material& m = scene.materials.at(0);
  EXPECT_EQ(m.emission, glm::dvec3(0.8, 0.4, 0.2));  // the base colour, not the emissive fallback
  EXPECT_EQ(m.diffuse, glm::dvec3(0.0));
  EXPECT_EQ(m.fresnel, rules::f64::F_DIELECTRIC);
  EXPECT_EQ(m.eta, glm::dvec3(1.0));
  EXPECT_FALSE(m.textures.has_value());
  EXPECT_THAT(scene.warnings, IsEmpty());
  // Nothing is reflected at any angle: the BRDF is 0.
  const rules::f64::BrdfParams p = materials::toParams64(m);
  for (double c : {1.0, 0.5, 0.05}) {
    const glm::dvec3 v(std::sqrt(1.0 - c * c), 0.0, c), l(-v.x, 0.0, v.z), n(0.0, 0.0, 1.0);
    EXPECT_EQ(rules::f64::brdf_evaluate(p, n, l, v), glm::dvec3(0.0)) << c;
  }
}

}  // namespace
}  // namespace facet::scene
