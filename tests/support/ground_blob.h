// A blob over the preview's ground (scenes/ground_plane.h): seen from far
// enough that the ground reaches from under the blob to several of its
// widths in front of it and the sky shows above, under a dim floor and sky
// with a broad light overhead. Needs FACET_CAGE_DIR.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "tests/support/blob_scene.h"
#include "tests/support/environment_maps.h"

namespace facet::testing {

inline scene::Scene blobOverGround() {
  scene::Scene s =
      blobUnder(lambertian(0.7),
                std::make_shared<const scene::EnvironmentMap>(ibl::testing::mapOf(
                    32, 16, [](glm::dvec3 d) { return glm::dvec3(0.1 + 4.0 * std::pow(std::max(d.y, 0.0), 8.0)); })),
                48);
  s.camera.eye = {0.0, 2.0, 9.0};
  s.camera.verticalFovDegrees = 40;
  return s;
}

}  // namespace facet::testing
