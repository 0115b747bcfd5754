// What `facet bench` hands Blender (analysis/peers/cycles_peer.h): each
// material as the Cycles BSDF that is the same function, or an error where
// there is none; the absorption coefficients; the bounce limits; the cages.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "analysis/peers/cycles_peer.h"
#include "rules/rules.h"
#include "tests/support/temp_dir.h"

namespace facet::peers {
namespace {

namespace fs = std::filesystem;

scene::ControlCage quad() {
  scene::ControlCage cage;
  cage.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  cage.faceVertexCounts = {4};
  cage.faceVertexIndices = {0, 3, 2, 1};
  return cage;
}

// A scene of one object per material, lit by a map as Cycles sees it.
scene::Scene sceneOf(const std::vector<materials::Material>& materials) {
  scene::Scene scene;
  scene.materials = materials;
  for (std::size_t i = 0; i < materials.size(); ++i)
    scene.objects.push_back({"object", quad(), int(i),
                             scene::Subdivision(i % 2 ? scene::Subdivision::None : scene::Subdivision::CatmullClark)});
  auto map = std::make_shared<scene::EnvironmentMap>();
  map->source = "courtyard.hdr";
  scene.environment.emplace();
  scene.environment->map = map;
  scene.environment->rotationDegrees = kCyclesMapRotationDegrees;
  scene.render.bounces = 12;
  scene.render.glossyBounces = 4;
  scene.render.transmissionBounces = 20;
  return scene;
}

materials::Material metal() {
  materials::Material m;
  m.name = "gold";
  m.fresnel = rules::f64::F_BLENDER_METALLIC;
  m.geometry = rules::f64::G_SMITH_GGX;
  m.f0 = {1.0, 0.71, 0.29};
  m.alpha = 0.09;
  return m;
}

materials::Material lambert() {
  materials::Material m;
  m.name = "floor";
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.eta = glm::dvec3(1.0);
  m.diffuse = glm::dvec3(0.5);
  return m;
}

materials::Material ruby() {
  materials::Material m;
  m.name = "ruby";
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.transmission = 1;
  m.alpha = 0;
  m.eta = glm::dvec3(1.77);
  m.attenuationColor = {0.9, 0.2, 0.3};
  m.attenuationDistance = 0.5;
  return m;
}

class CyclesPeer : public testing::TempDirTest {
 protected:
  nlohmann::json described(const scene::Scene& scene) {
    return nlohmann::json::parse(std::ifstream(describeForCycles(scene, dir_)));
  }
};

TEST_F(CyclesPeer, DescribesMetalLambertAndAbsorbingGlass) {
  const nlohmann::json d = described(sceneOf({metal(), lambert(), ruby()}));
  ASSERT_EQ(d["objects"].size(), 3u);
  const nlohmann::json& gold = d["objects"][0]["material"];
  EXPECT_EQ(gold["kind"], "metal");
  EXPECT_NEAR(gold["roughness"].get<double>(), 0.3, 1e-12);  // Cycles' roughness is sqrt(alpha)
  EXPECT_NEAR(gold["base"][1].get<double>(), 0.71, 1e-12);
  EXPECT_EQ(d["objects"][1]["material"]["kind"], "diffuse");
  EXPECT_EQ(d["objects"][1]["material"]["albedo"][0], 0.5);
  const nlohmann::json& glass = d["objects"][2]["material"];
  EXPECT_EQ(glass["kind"], "glass");
  EXPECT_NEAR(glass["ior"].get<double>(), 1.77, 1e-12);
  // Beer-Lambert: exp(-sigma d) is the attenuation colour at its distance.
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(std::exp(-glass["absorption"][c].get<double>() * 0.5), ruby().attenuationColor[c], 1e-12);
  // Catmull-Clark cages at the bench's levels, polygons as authored at 0,
  // each written as an OBJ beside the description.
  EXPECT_EQ(d["objects"][0]["levels"], kCyclesSubdivisionLevels);
  EXPECT_EQ(d["objects"][1]["levels"], 0);
  std::ifstream obj(d["objects"][0]["cage"].get<std::string>());
  std::string text((std::istreambuf_iterator<char>(obj)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("f 1 4 3 2"), std::string::npos) << text;
}

TEST_F(CyclesPeer, KindLimitsAreCappedByTheTotal) {
  const nlohmann::json b = described(sceneOf({metal()}))["bounces"];
  EXPECT_EQ(b["total"], 12);
  EXPECT_EQ(b["glossy"], 4);
  EXPECT_EQ(b["diffuse"], 12);       // no limit of its own
  EXPECT_EQ(b["transmission"], 12);  // 20, above the total
}

TEST_F(CyclesPeer, RefusesWhatCyclesWouldRenderDifferently) {
  const auto refused = [&](const scene::Scene& scene, const std::string& words) {
    try {
      describeForCycles(scene, dir_);
      ADD_FAILURE() << "described a scene that should be refused (" << words << ")";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  materials::Material schlick = metal();
  schlick.fresnel = rules::f64::F_SCHLICK;
  refused(sceneOf({schlick}), "metallic Fresnel");
  materials::Material correlated = metal();
  correlated.geometry = rules::f64::G_SMITH_GGX_CORRELATED;
  refused(sceneOf({correlated}), "separable Smith G");
  materials::Material coated = metal();
  coated.clearcoat = 1;
  refused(sceneOf({coated}), "a coat");
  materials::Material velvet = lambert();
  velvet.sheenColor = glm::dvec3(0.5);
  refused(sceneOf({velvet}), "sheen");
  materials::Material filmed = metal();
  filmed.iridescence = 1;
  refused(sceneOf({filmed}), "a thin film");
  materials::Material thin = ruby();
  thin.thinWalled = true;
  refused(sceneOf({thin}), "closed volume");
  scene::Scene lit = sceneOf({metal()});
  lit.lights.emplace_back();
  refused(lit, "punctual lights");
  scene::Scene turned = sceneOf({metal()});
  turned.environment->rotationDegrees = 0;
  refused(turned, "270 degrees");
}

}  // namespace
}  // namespace facet::peers
