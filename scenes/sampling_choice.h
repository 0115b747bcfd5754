// How a picture takes its camera samples where nothing states it
// (docs/rendering.md, "Converged by default"): one pass of a 4 x 4 net where
// every sample shades without random numbers, so that the pixel's area is
// the only integral left; adaptive rounds to the noise threshold where
// anything is sampled at random. Stated sampling always wins.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace facet::scene {

// The samples per pixel of a chosen single pass: the adaptive rounds' least
// (4 rounds of 4), as one better stratified net.
inline constexpr int kAntiAliasingSpp = 16;

// Whether every camera sample of `scene` shades without random numbers:
// no paths, no environment sampled or filtered, and no blended surface
// (glTF's BLEND is drawn per ray). Punctual lights, the split sum, textures
// and MASK's cutouts are evaluated, not sampled. The scene's light transport
// must be stated or chosen already (scenes/light_transport.h).
bool shadesWithoutNoise(const Scene& scene);

// The sampling chosen for `scene`, its light transport stated or chosen:
// where its sampling is Chosen, sets one pass of kAntiAliasingSpp or
// adaptive rounds, and returns why for the summary line ("paths are
// random"); else leaves it and returns "".
std::string chooseSampling(Scene& scene);

}  // namespace facet::scene
