// What a scene uses (scenes/scene_features.h): each feature is seen on the
// object that has it, a material no object uses adds none, and paths' lobe
// limits count only where paths continue.
#include <gtest/gtest.h>

#include <filesystem>

#include "scenes/obj_cage.h"
#include "scenes/scene_features.h"
#include "tests/support/blob_scene.h"

namespace facet::scene {
namespace {

Scene plainCube() {
  Scene s;
  s.materials.push_back(facet::testing::lambertian(0.5));
  Object cube;
  cube.cage = loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  s.objects.push_back(cube);
  return s;
}

TEST(SceneFeatures, APlainSceneUsesNone) {
  const SceneFeatures f = sceneFeatures(plainCube());
  EXPECT_FALSE(f.perHitMaterials || f.textures || f.emission || f.transmission || f.anisotropy || f.clearcoat ||
               f.sheen || f.channels || f.culling || f.cutouts || f.paths || f.lobeLimits);
}

TEST(SceneFeatures, EachMaterialFeatureIsSeenOnTheObjectThatUsesIt) {
  Scene s = plainCube();
  materials::Material& m = s.materials[0];
  m.emission = glm::dvec3(1.0);
  m.transmission = 1.0;
  m.anisotropy = 0.5;
  m.clearcoat = 1.0;
  m.sheenColor = glm::dvec3(0.2);
  m.textures.emplace();
  const SceneFeatures f = sceneFeatures(s);
  EXPECT_TRUE(f.emission && f.transmission && f.anisotropy && f.clearcoat && f.sheen && f.perHitMaterials &&
              f.textures);
}

TEST(SceneFeatures, AMaterialNoObjectUsesAddsNone) {
  Scene s = plainCube();
  materials::Material unused = s.materials[0];
  unused.clearcoat = 1.0;
  unused.transmission = 1.0;
  unused.emission = glm::dvec3(1.0);
  s.materials.push_back(unused);
  const SceneFeatures f = sceneFeatures(s);
  EXPECT_FALSE(f.clearcoat || f.transmission || f.emission);
}

TEST(SceneFeatures, ObjectsCullAndCutOutAndCarryChannels) {
  Scene s = plainCube();
  s.objects[0].oneSided = true;
  s.objects[0].alphaMode = AlphaMode::Mask;
  s.objects[0].cage.colors = {glm::dvec3(1.0)};
  s.objects[0].cage.faceVertexColors.assign(s.objects[0].cage.faceVertexIndices.size(), 0);
  SceneFeatures f = sceneFeatures(s);
  EXPECT_TRUE(f.culling && f.cutouts && f.channels);
  s.objects[0].alphaMode = AlphaMode::Blend;  // a blended surface passes rays as a cutout does
  EXPECT_TRUE(sceneFeatures(s).cutouts);
  s.materials[0].transmission = 1.0;  // glass is never culled: paths see its inside
  EXPECT_FALSE(sceneFeatures(s).culling);
}

TEST(SceneFeatures, LobeLimitsCountOnlyWherePathsContinue) {
  Scene s = plainCube();
  s.render.diffuseBounces = 2;
  EXPECT_FALSE(sceneFeatures(s).lobeLimits);
  s.render.bounces = 4;
  EXPECT_TRUE(sceneFeatures(s).paths && sceneFeatures(s).lobeLimits);
}

}  // namespace
}  // namespace facet::scene
