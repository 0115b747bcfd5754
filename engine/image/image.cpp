#include "engine/image/image.h"

#include <stdexcept>
#include <string>

namespace facet {

Image::Image(int w, int h) : width(w), height(h) {
  if (w <= 0 || h <= 0 || w > 65536 || h > 65536)
    throw std::invalid_argument("image size " + std::to_string(w) + "x" + std::to_string(h) +
                                " is outside 1x1 .. 65536x65536");
  const std::size_t n = pixelCount();
  beauty.assign(n, glm::vec4(0.0f));
  depth.assign(n, std::numeric_limits<float>::infinity());
  position.assign(n, glm::vec3(0.0f));
  geometricNormal.assign(n, glm::vec3(0.0f));
  shadingNormal.assign(n, glm::vec3(0.0f));
  patchId.assign(n, kNoId);
  faceId.assign(n, kNoId);
  uv.assign(n, glm::vec2(0.0f));
  texcoord.assign(n, glm::vec2(0.0f));
}

}  // namespace facet
