#include "scenes/ground_plane.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "scenes/scene_file.h"

namespace facet::scene {
namespace {

// A dielectric of index 1 is no interface: F = 0 at every angle, where
// Schlick's would still rise at grazing; so no specular lobe at all.
materials::Material lambertian(const char* name, double albedo) {
  materials::Material m = defaultMaterial();
  m.name = name;
  m.fresnel = rules::f64::F_DIELECTRIC;
  m.eta = glm::dvec3(1.0);
  m.diffuse = glm::dvec3(albedo);
  return m;
}

Object groundSquare(const Aabb& bounds, double height) {
  const double half = kGroundHalfWidth * bounds.diagonal();
  const glm::dvec3 c = bounds.centre();
  Object ground;
  ground.name = "ground";
  ground.subdivision = Subdivision::None;
  ground.cage.source = "the preview's ground";
  // Counter-clockwise seen from above: the normal is +y.
  ground.cage.positions = {{c.x - half, height, c.z - half},
                           {c.x - half, height, c.z + half},
                           {c.x + half, height, c.z + half},
                           {c.x + half, height, c.z - half}};
  ground.cage.faceVertexCounts = {4};
  ground.cage.faceVertexIndices = {0, 1, 2, 3};
  return ground;
}

// The ground's square appended to `scene` in its own material.
Object& addSquare(Scene& scene, const GroundScenes& ground) {
  scene.objects.push_back(ground.square);
  scene.objects.back().material = int(scene.materials.size());
  scene.materials.push_back(ground.squareMaterial);
  return scene.objects.back();
}

}  // namespace

double lowestPoint(const SceneGeometry& geometry) {
  constexpr int kGrid = 8;  // intervals per side of each patch
  double lowest = std::numeric_limits<double>::infinity();
  for (const ObjectGeometry& object : geometry.objects)
    for (int p = 0; p < object.surface.patchCount(); ++p)
      for (int j = 0; j <= kGrid; ++j)
        for (int i = 0; i <= kGrid; ++i) {
          const BezierSample s =
              evaluateBezierPatch(object.surface.bezierPatch(p), double(i) / kGrid, double(j) / kGrid);
          lowest = std::min(lowest, s.position.y);
        }
  return lowest;
}

GroundScenes groundScenes(const Scene& model) {
  if (!model.environment) throw std::invalid_argument("the ground needs an environment to light it");
  if (model.objects.empty()) throw std::invalid_argument("the ground needs a model to stand under");
  const SceneGeometry geometry = buildGeometry(model);
  const Object ground = groundSquare(geometry.bounds, lowestPoint(geometry));

  Scene lit = model;
  lit.objects.clear();
  lit.materials.clear();
  lit.lights.clear();
  lit.render.bounces = 0;
  lit.render.bouncesStated = true;
  if (lit.environment->method == IblMethod::Prefiltered) lit.environment->method = IblMethod::Filtered;
  lit.environment->occlusion = true;
  lit.environment->methodStated = true;
  lit.environment->samples = std::min(lit.environment->samples, 4);

  GroundScenes scenes{lit, lit};
  // Nothing stands on the ground alone, so its shadow rays could only pass:
  // without them it draws the same samples and values, at a fraction of the cost.
  scenes.ground.environment->occlusion = false;
  scenes.ground.materials = {lambertian("ground", 1.0)};
  scenes.ground.objects = {ground};
  scenes.ground.objects.back().material = 0;

  // The holdout is black to the camera and reflects nothing: the ground's
  // share of its pixels is all the holdout's radiance.
  scenes.holdout.materials = {lambertian("holdout", 0.0), lambertian("ground", 1.0)};
  for (Object object : model.objects) {
    object.material = 0;
    object.holdout = true;
    scenes.holdout.objects.push_back(std::move(object));
  }
  scenes.holdout.objects.push_back(ground);
  scenes.holdout.objects.back().material = 1;

  scenes.square = ground;
  scenes.squareMaterial = lambertian("ground", 1.0);
  return scenes;
}

Scene holdoutWithPaths(const GroundScenes& ground, const Scene& model) {
  Scene holdout = ground.holdout;
  holdout.materials = model.materials;
  holdout.textures = model.textures;
  holdout.objects = model.objects;
  for (Object& object : holdout.objects) object.holdout = true;
  addSquare(holdout, ground);
  holdout.render.bounces = model.render.bounces;
  holdout.render.diffuseBounces = model.render.diffuseBounces;
  holdout.render.glossyBounces = model.render.glossyBounces;
  holdout.render.transmissionBounces = model.render.transmissionBounces;
  return holdout;
}

Scene withShadowCatcher(Scene scene, const GroundScenes& ground) {
  addSquare(scene, ground).shadowCatcher = true;
  return scene;
}

}  // namespace facet::scene
