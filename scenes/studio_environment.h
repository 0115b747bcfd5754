// The lighting of a scene that brings neither lights nor an environment:
// the shipped photographic studio (scenes/environments/studio.exr: two
// bright lamps over a pale floor and dark walls), built into the program
// and turned so that, from the default view, the lamps light the model
// from above and behind its left shoulder and show in a glossy material's
// highlights (docs/preview.md, "The default light").
#pragma once

#include "scenes/scene.h"

namespace facet::scene {

// The map's `source`, which is how summaries name it.
inline constexpr const char* kStudioEnvironmentName = "default studio environment, studio.exr turned 90 degrees";

// The turn about +y that places the lamps for the default view.
inline constexpr double kStudioRotationDegrees = 90.0;

// 1024 x 512 texels, decoded from the program's copy of studio.exr.
EnvironmentMap studioEnvironmentMap();

// The map, turned, decoded once and shared by every scene that gets it;
// its method and samples are facet's to choose.
Environment studioEnvironment();

bool isStudioEnvironment(const Environment& environment);

}  // namespace facet::scene
