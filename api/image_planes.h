// The engine's Image as the public API's named AOV planes, and back: both
// directions name the planes alike (include/facet/image.h).
#pragma once

#include "engine/image/image.h"
#include "facet/image.h"

namespace facet::v0 {

Image publicImage(const facet::Image& image);

// Throws Error (BadInput) naming the plane when `image` lacks one the engine
// writes, or a plane's size is not width x height x its channels.
facet::Image engineImage(const Image& image);

}  // namespace facet::v0
