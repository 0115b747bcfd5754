// The light transport chosen by the scene (scenes/light_transport.h): paths
// with Cycles' limits where a continuation can hit, direct light where none
// can, and what the scene states always kept.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scenes/light_transport.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_file.h"
#include "scenes/studio_environment.h"
#include "tests/support/blob_scene.h"
#include "tests/support/cages.h"

namespace facet::scene {
namespace {

// One object under the default studio light, nothing of light transport said.
Scene unsaid(ControlCage cage, const char* name) {
  Scene s;
  s.materials.push_back(facet::testing::lambertian(0.5));
  s.materials.front().name = "grey";
  Object object;
  object.name = name;
  object.cage = std::move(cage);
  s.objects.push_back(std::move(object));
  s.camera.eye = {0.5, 3.0, 4.0};
  s.render.width = s.render.height = 32;
  s.render.bouncesStated = false;
  s.environment = studioEnvironment();
  return s;
}

Scene cube() { return unsaid(loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj"), "cube"); }
Scene torus() { return unsaid(testing::torusCage(12, 8, 1.0, 0.35), "torus"); }

LightTransport choose(const Scene& s) { return chooseLightTransport(s, buildGeometry(s)); }

Scene withStatedBounces(Scene s, int bounces) {
  s.render.bouncesStated = true;
  s.render.bounces = bounces;
  return s;
}

TEST(LightTransport, OneConvexObjectGetsDirectLightAsItIs) {
  const Scene s = cube();
  const LightTransport t = choose(s);
  EXPECT_EQ(t.bounces, 0);
  EXPECT_EQ(t.note, "direct light only: one convex closed object, seen from outside; no continuation can hit");
  EXPECT_FALSE(changesScene(t, s));  // the split sum stays: nothing is lost
  EXPECT_TRUE(t.warnings.empty());
}

TEST(LightTransport, AConcaveObjectGetsCyclesLimitsAndASampledEnvironment) {
  Scene s = torus();
  const LightTransport t = choose(s);
  EXPECT_EQ(t.bounces, kChosenBounces);
  EXPECT_EQ(t.diffuseBounces, kChosenDiffuseBounces);
  EXPECT_EQ(t.glossyBounces, kChosenGlossyBounces);
  EXPECT_EQ(t.transmissionBounces, kChosenTransmissionBounces);
  EXPECT_TRUE(t.samplesEnvironment);
  EXPECT_EQ(t.environmentPairs, kChosenEnvironmentPairs);
  EXPECT_EQ(t.note,
            "paths: 12 bounces (diffuse 4, glossy 4, transmission 12), environment sampled (2 pairs per camera "
            "sample): 'torus' has holes, handles or open edges");
  ASSERT_TRUE(changesScene(t, s));
  applyLightTransport(t, s);
  EXPECT_EQ(s.environment->method, IblMethod::Sampled);
  EXPECT_TRUE(s.environment->occlusion);
  EXPECT_EQ(s.environment->samples, kChosenEnvironmentPairs);
  EXPECT_TRUE(pathsCountEnvironmentOnce(s.render.bounces, s.environment));
}

// The pairs are chosen with the paths, and only where nothing said them.
TEST(LightTransport, StatedEnvironmentSamplesAreKept) {
  Scene s = torus();
  s.environment->samples = 5;
  s.environment->samplesStated = true;
  const LightTransport t = choose(s);
  EXPECT_EQ(t.bounces, kChosenBounces);
  EXPECT_EQ(t.environmentPairs, 0);
  EXPECT_EQ(t.note.find("per camera sample"), std::string::npos) << t.note;
  applyLightTransport(t, s);
  EXPECT_EQ(s.environment->samples, 5);

  Scene sampled = torus();
  sampled.environment->method = IblMethod::Sampled;
  sampled.environment->methodStated = true;
  EXPECT_EQ(choose(sampled).note,
            "paths: 12 bounces (diffuse 4, glossy 4, transmission 12), 2 pairs of the "
            "environment per camera sample: 'torus' has holes, handles or open edges");

  Scene stated = withStatedBounces(torus(), 3);
  const int samples = stated.environment->samples;
  applyLightTransport(choose(stated), stated);
  EXPECT_EQ(stated.environment->samples, samples);
}

TEST(LightTransport, AStatedLobeLimitIsKept) {
  Scene s = torus();
  s.render.glossyBounces = 1;
  const LightTransport t = choose(s);
  EXPECT_EQ(t.glossyBounces, 1);
  EXPECT_EQ(t.diffuseBounces, kChosenDiffuseBounces);
}

TEST(LightTransport, StatedBouncesWin) {
  Scene s = withStatedBounces(torus(), 3);
  s.environment->method = IblMethod::Filtered;
  s.environment->methodStated = true;
  const LightTransport t = choose(s);
  EXPECT_EQ(t.bounces, 3);
  EXPECT_EQ(t.diffuseBounces, -1);
  EXPECT_FALSE(t.samplesEnvironment);
  EXPECT_TRUE(t.note.empty());
  EXPECT_FALSE(changesScene(t, s));

  s.render.bounces = 0;
  EXPECT_EQ(choose(s).bounces, 0);
}

TEST(LightTransport, StatedBouncesSampleAnUnsaidEnvironmentAndSaySo) {
  const LightTransport t = choose(withStatedBounces(torus(), 2));
  EXPECT_EQ(t.bounces, 2);
  EXPECT_TRUE(t.samplesEnvironment);
  EXPECT_EQ(t.note, "environment sampled: the stated bounces need its shadow rays");
}

TEST(LightTransport, StatedBouncesOnAConvexObjectCastNone) {
  const LightTransport t = choose(withStatedBounces(cube(), 8));
  EXPECT_EQ(t.bounces, 0);
  EXPECT_EQ(t.note, "paths: none cast: one convex closed object, seen from outside; no continuation can hit");
  EXPECT_FALSE(t.samplesEnvironment);
}

TEST(LightTransport, GlassIsNeverSilentlyBlack) {
  Scene s = cube();
  s.materials.front().transmission = 1.0;
  s.materials.front().name = "glass";
  const LightTransport chosen = choose(s);
  EXPECT_EQ(chosen.bounces, kChosenBounces);  // a convex glass cube still bounces: its inside
  EXPECT_EQ(chosen.note,
            "paths: 12 bounces (diffuse 4, glossy 4, transmission 12), environment sampled (2 pairs per camera "
            "sample): 'glass' transmits");
  EXPECT_TRUE(chosen.warnings.empty());

  s.render.bouncesStated = true;
  const LightTransport stated = choose(s);
  EXPECT_EQ(stated.bounces, 0);
  ASSERT_EQ(stated.warnings.size(), 1u);
  EXPECT_EQ(stated.warnings.front(),
            "'glass' transmits, but the bounces are stated 0: no path passes through it and it shows nothing behind it");
}

// A single pane of glass with a volume behind it bends light in and never
// out: said, whatever the bounces; a thin wall or a closed solid is not.
TEST(LightTransport, AVolumeOfGlassThatIsNotClosedIsSaid) {
  Scene s = unsaid(testing::singleFace({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}), "pane");
  s.materials.front().transmission = 1.0;
  for (bool stated : {false, true}) {
    s.render.bouncesStated = stated;
    const LightTransport t = choose(s);
    ASSERT_FALSE(t.warnings.empty());
    EXPECT_EQ(t.warnings.front().rfind("'pane' transmits into a volume, but its surface does not close around a "
                                       "solid",
                                       0),
              0u)
        << t.warnings.front();
  }
  s.render.bouncesStated = false;
  s.materials.front().thinWalled = true;
  EXPECT_TRUE(choose(s).warnings.empty());
}

TEST(LightTransport, AStatedPrefilteredEnvironmentKeepsDirectLightAndSaysWhichOptionTraces) {
  Scene s = torus();
  s.environment->methodStated = true;
  const LightTransport t = choose(s);
  EXPECT_EQ(t.bounces, 0);
  EXPECT_NE(t.note.find("give --ibl sampled"), std::string::npos) << t.note;
  EXPECT_TRUE(t.warnings.empty());
  s.materials.front().transmission = 1.0;
  EXPECT_EQ(choose(s).warnings.size(), 1u);
}

TEST(LightTransport, ParityStatesWhatWasUnsaid) {
  Scene s = torus();
  leaveNothingToChoose(s);
  EXPECT_TRUE(s.render.bouncesStated);
  EXPECT_EQ(s.render.bounces, 0);
  EXPECT_EQ(s.environment->method, IblMethod::Prefiltered);

  Scene paths = torus();
  paths.render.bounces = 4;
  leaveNothingToChoose(paths);
  EXPECT_EQ(paths.environment->method, IblMethod::Sampled);  // the stated bounces need it
  EXPECT_TRUE(paths.environment->methodStated);
}

TEST(LightTransport, AModelFileLeavesItToChoose) {
  const Scene s = loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  EXPECT_FALSE(s.render.bouncesStated);
  ASSERT_TRUE(s.environment);
  EXPECT_FALSE(s.environment->methodStated);
  EXPECT_FALSE(s.environment->samplesStated);
}

// What facet bench and facet ibl-chart measure is what they set.
TEST(LightTransport, AMeasurementLoadsTheSceneStated) {
  const Scene s = loadStatedScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  EXPECT_TRUE(s.render.bouncesStated);
  EXPECT_EQ(s.render.bounces, 0);
  ASSERT_TRUE(s.environment);
  EXPECT_TRUE(s.environment->methodStated);
  EXPECT_FALSE(leavesLightTransportUnsaid(s));
}

}  // namespace
}  // namespace facet::scene
