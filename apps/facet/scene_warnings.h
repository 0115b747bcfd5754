// A scene's warnings (scenes/scene.h) on stderr, whatever --quiet says: they
// tell that the render differs from what the file says, as the
// environment's clamped texels do.
#pragma once

#include "scenes/scene.h"

namespace facet::cli {

// One line "facet: warning: ..." per warning.
void printSceneWarnings(const scene::Scene& scene);

}  // namespace facet::cli
