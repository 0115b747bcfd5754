// How fast the camera samples' pixel integral converges: relative RMSE of
// the beauty against samples per pixel, on silhouette pixels (an edge
// crosses the pixel) and smooth ones (no edge near) apart, under the
// prefiltered split sum, whose shading has no noise of its own
// (docs/rendering.md, "Rays"; `facet ibl-chart`).
#pragma once

#include <vector>

#include "engine/renderer.h"
#include "scenes/scene.h"

namespace facet::analysis {

struct AntialiasingPoint {
  int samplesPerPixel = 0;
  double silhouetteRmse = 0;  // relative to the reference's mean covered radiance
  double smoothRmse = 0;
};

struct AntialiasingCurve {
  int referenceSamples = 0;  // samples per pixel of the reference, 16 x the largest measured
  std::vector<AntialiasingPoint> points;
  double silhouetteSlope = 0;  // log-log, over the points with 4 or more samples; NaN with fewer than two
  double smoothSlope = 0;
};

// `scene` must have an environment; its method is set to prefiltered.
// `samplesPerPixel`: ascending powers of 4.
AntialiasingCurve measureAntialiasing(Renderer& renderer, scene::Scene scene, const std::vector<int>& samplesPerPixel,
                                      Backend backend);

}  // namespace facet::analysis
