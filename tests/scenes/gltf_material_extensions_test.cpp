// glTF material extensions facet reads beyond those of transmission
// (gltf_transmission_test.cpp): KHR_materials_emissive_strength.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "engine/cpu/reference_renderer.h"
#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_gltf.h"

namespace facet::scene {
namespace {

using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::ThrowsMessage;

class GltfMaterialExtensions : public facet::testing::TempDirTest {
 protected:
  // The textured quad of one black dielectric, double-sided, with `members` added.
  std::filesystem::path write(const std::string& name, const nlohmann::json& members) {
    nlohmann::json m = {{"doubleSided", true},
                        {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0.0}}}};
    m.update(members);
    return facet::testing::writeTexturedQuad(dir_, name, {{"materials", {m}}});
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

}  // namespace
}  // namespace facet::scene
