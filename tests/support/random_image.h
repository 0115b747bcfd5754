// An image with random values in every plane, and some misses, for round
// trips through files.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "engine/image/image.h"

namespace facet::testing {

inline Image randomImage(int w, int h) {
  Image image(w, h);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    if (i % 5 == 0) continue;  // leave some misses
    image.beauty[i] = {u(rng), u(rng), u(rng), 1.0f};
    image.depth[i] = std::abs(u(rng));
    image.position[i] = {u(rng), u(rng), u(rng)};
    image.geometricNormal[i] = {u(rng), u(rng), u(rng)};
    image.shadingNormal[i] = {u(rng), u(rng), u(rng)};
    image.patchId[i] = std::uint32_t(rng());
    image.faceId[i] = std::uint32_t(rng());
    image.uv[i] = {u(rng), u(rng)};
    image.texcoord[i] = {u(rng), u(rng)};
  }
  return image;
}

}  // namespace facet::testing
