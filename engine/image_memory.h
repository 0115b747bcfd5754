// Whether the images of a render fit in the memory one facet process lets
// itself use (scenes/memory_budget.h, docs/reliability.md "Limits"), checked
// before anything is allocated for them: the CLI and both APIs apply it alike.
#pragma once

#include <optional>
#include <string>

#include "engine/image/pixel_rect.h"
#include "scenes/scene.h"

namespace facet {

// Whether `images` images of the scene's size (or of the crop) fit in
// scene::memoryLimit().
bool imagesFitInMemory(const scene::Scene& scene, int images, const std::optional<PixelRect>& crop = {});

// Throws std::invalid_argument unless `images` images of the scene's size,
// or of the crop of it that is rendered, fit in scene::memoryLimit();
// `sizeSource` names where the size came from.
void checkImagesFitInMemory(const scene::Scene& scene, int images, const std::string& sizeSource,
                            const std::optional<PixelRect>& crop = {});

}  // namespace facet
