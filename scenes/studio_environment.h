// The lighting of a scene that brings neither lights nor an environment: a
// neutral grey studio, a soft gradient from a dark floor to a lighter
// ceiling with three broad soft boxes (key, fill, rim), built in memory.
// Its dynamic range is kept near 50:1, broad lobes on a smooth ground, so
// that the prefiltered method, the default, lights it accurately
// (docs/preview.md).
#pragma once

#include "scenes/scene.h"

namespace facet::scene {

// The map's `source`, which is how summaries name it.
inline constexpr const char* kStudioEnvironmentName = "default studio environment";

// 256 x 128 texels, equal in R, G and B.
EnvironmentMap studioEnvironmentMap();

// The map, prefiltered, shared by every scene that gets it.
Environment studioEnvironment();

bool isStudioEnvironment(const Environment& environment);

}  // namespace facet::scene
