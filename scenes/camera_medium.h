// The medium the camera starts in (docs/rendering.md, "The camera inside a
// medium"): an eye inside an absorbing solid sees everything through it, so
// its camera rays take Beer-Lambert's factor over their first segment and
// its paths start in that medium. A scene states no medium; it is found from
// the geometry, once per render, alike for both backends.
#pragma once

#include <glm/vec3.hpp>

#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::scene {

struct CameraMedium {
  int object = -1;        // the solid around the eye; -1 in air
  glm::dvec3 sigma{0.0};  // its absorption coefficient (rules/shading/absorption.h)
};

// The innermost of the scene's absorbing solids (a transmissive material
// that absorbs, not thin-walled, on a surface that encloses a solid) whose
// inside holds `point`, by the parity of three rays' crossings (their majority) of a fine
// tessellation of each one's limit surface; -1 where none does. Free for a
// scene without such a solid.
int absorbingSolidAround(const Scene& scene, const SceneGeometry& geometry, const glm::dvec3& point);

CameraMedium cameraMedium(const Scene& scene, const SceneGeometry& geometry);

}  // namespace facet::scene
