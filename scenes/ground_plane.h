// The ground a preview stands its model on: a shadow catcher, rendered as two
// scenes beside the model's own (docs/preview-stage.md, "The ground"), whose
// ratio engine/image/catcher_composite.h turns into the model's shadow on
// the background.
#pragma once

#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::scene {

// The ground's half-width, in diagonals of the model's bounding box: wide
// enough for the shadow of light a few degrees above the horizon.
inline constexpr double kGroundHalfWidth = 10.0;

struct GroundScenes {
  Scene holdout;  // the model, black and held out of the camera rays (Object::holdout), standing on the ground
  Scene ground;   // the ground alone
  // The ground's square and its white Lambertian material, for the scenes
  // of a model whose paths run (below).
  Object square;
  materials::Material squareMaterial;
};

// Both lit by the model's environment with shadow rays: its own method
// where that casts them (sampled, filtered), else sampled; occlusion on.
// The ground is a white, purely diffuse square, horizontal in the
// environment's frame (+y up), under the middle of the model's bounding box
// and touching its lowest point. Camera and render settings are the model's.
// Throws std::invalid_argument for a scene without an environment or objects.
GroundScenes groundScenes(const Scene& model);

// `scene` (the model's, with paths) with the ground's catcher added: the
// model's continuation rays see the ground its shadows fall on, its camera
// rays the background as before.
Scene withShadowCatcher(Scene scene, const GroundScenes& ground);

// The holdout of a model whose paths run (`model`: its scene with the light
// transport chosen): the model in its own materials on the ground, the
// paths' bounces and limits, the holdout's environment, and held out of
// the camera rays: black where they hit it, as the composite reads it. Its
// ground then also receives what the model sends onto it: light through
// glass, gold's reflection.
Scene holdoutWithPaths(const GroundScenes& ground, const Scene& model);

// The lowest height (y) of the limit surface, each patch evaluated on a
// 9 x 9 grid of its (u, v).
double lowestPoint(const SceneGeometry& geometry);

}  // namespace facet::scene
