// What a scene uses, decided once per render: every kernel variant the GPU
// path compiles follows from this record, so that a feature no object uses
// costs a scene nothing (as pbrt-v4's haveBasicEvalMaterial and Mitsuba's
// m_has_* flags do). The CPU reference decides per hit instead, from the
// material it meets.
#pragma once

#include "scenes/scene.h"

namespace facet::scene {

struct SceneFeatures {
  // Some object's material takes its glTF parameters per hit: it reads a
  // texture, or vertex colours multiply its base colour.
  bool perHitMaterials = false;
  bool textures = false;  // per-hit materials, or any texture to read (a cutout's alpha too)
  bool emission = false;
  bool transmission = false;
  bool anisotropy = false;
  bool clearcoat = false;
  bool sheen = false;
  bool iridescence = false;
  // Some object has vertex colours or a second set of texture coordinates.
  bool channels = false;
  bool culling = false;  // some object culls its back faces (cullsBackFaces)
  bool cutouts = false;  // some object has a cutout (hasCutout)
  bool blends = false;   // some object's cutout is glTF's BLEND, drawn per ray
  bool shadowCatcher = false;  // some object catches shadows (Object::shadowCatcher): emission's slot holds its rest
  bool holdout = false;        // some object is held out of the camera rays (Object::holdout)
  bool paths = false;    // paths continue past the camera rays' hits
  bool lobeLimits = false;  // paths, and some lobe kind has a limit of its own
};

SceneFeatures sceneFeatures(const Scene& scene);

}  // namespace facet::scene
