// The solid around the eye (scenes/camera_medium.h): found by the parity of
// a ray's crossings, innermost first, among the absorbing solids alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "materials/material.h"
#include "scenes/camera_medium.h"
#include "scenes/obj_cage.h"
#include "scenes/scene_geometry.h"

namespace facet::scene {
namespace {

materials::Material glass(bool absorbs, bool thinWalled = false) {
  materials::MaterialSpec spec;
  spec.name = "glass";
  spec.alpha = 0.0;
  spec.ior = glm::dvec3(1.5);
  spec.transmission = 1.0;
  spec.thinWalled = thinWalled;
  if (thinWalled) spec.thickness = 0.1;
  if (absorbs) {
    spec.attenuationColor = glm::dvec3(0.5, 0.6, 0.7);
    spec.attenuationDistance = 2.0;
  }
  return materials::buildMaterial(spec, [](std::string_view field) { return std::string(field); });
}

// A cube as authored, `scale` times the unit cage's [-1, 1]^3, of material `material`.
Object cube(double scale, int material, Subdivision subdivision = Subdivision::None) {
  Object object;
  object.name = "cube " + std::to_string(scale);
  object.cage = loadObjCage(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  for (glm::dvec3& p : object.cage.positions) p *= scale;
  object.material = material;
  object.subdivision = subdivision;
  return object;
}

Scene nested() {
  Scene s;
  s.materials = {glass(true), glass(true)};
  s.objects.push_back(cube(3.0, 0));
  s.objects.push_back(cube(1.0, 1));
  return s;
}

TEST(CameraMedium, ThePointsInsideAnAbsorbingSolidAreFoundInnermostFirst) {
  const Scene scene = nested();
  const SceneGeometry geometry = buildGeometry(scene);
  EXPECT_EQ(absorbingSolidAround(scene, geometry, {0.1, 0.2, 0.3}), 1);
  EXPECT_EQ(absorbingSolidAround(scene, geometry, {-0.9, 0.95, -0.5}), 1);
  EXPECT_EQ(absorbingSolidAround(scene, geometry, {2.0, 0.2, 0.3}), 0);
  EXPECT_EQ(absorbingSolidAround(scene, geometry, {0.3, -2.9, 2.5}), 0);
  EXPECT_EQ(absorbingSolidAround(scene, geometry, {5.0, 0.0, 0.0}), -1);
  EXPECT_EQ(absorbingSolidAround(scene, geometry, {0.0, 0.0, -3.5}), -1);
}

TEST(CameraMedium, TheEyeTakesTheAbsorptionOfItsSolid) {
  Scene scene = nested();
  scene.camera.eye = {0.2, -0.1, 0.4};
  const CameraMedium medium = cameraMedium(scene, buildGeometry(scene));
  EXPECT_EQ(medium.object, 1);
  const glm::dvec3 sigma = materials::transmissionParams64(scene.materials[1]).sigma;
  EXPECT_GT(sigma.x, 0.0);
  EXPECT_EQ(medium.sigma, sigma);
  scene.camera.eye = {0.0, 0.0, 8.0};
  EXPECT_EQ(cameraMedium(scene, buildGeometry(scene)).object, -1);
  EXPECT_EQ(cameraMedium(scene, buildGeometry(scene)).sigma, glm::dvec3(0.0));
}

TEST(CameraMedium, OnlyAnAbsorbingSolidIsAMedium) {
  // Clear glass, a thin wall and an opaque material hold no medium; a
  // Catmull-Clark limit surface is found as a mesh as authored is.
  Scene scene;
  scene.materials = {glass(false), glass(true, true), materials::Material{}, glass(true)};
  for (int material = 0; material < 4; ++material) {
    scene.objects = {cube(1.0, material, Subdivision::CatmullClark)};
    EXPECT_EQ(absorbingSolidAround(scene, buildGeometry(scene), {0.05, 0.1, -0.05}), material == 3 ? 0 : -1)
        << material;
  }
  // Between the cage's corner and the limit surface, which shrinks inside it.
  EXPECT_EQ(absorbingSolidAround(scene, buildGeometry(scene), {0.95, 0.95, 0.95}), -1);
}

}  // namespace
}  // namespace facet::scene
