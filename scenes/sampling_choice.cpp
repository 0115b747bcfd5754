#include "scenes/sampling_choice.h"

#include <algorithm>

namespace facet::scene {

namespace {

bool blends(const Scene& scene) {
  return std::any_of(scene.objects.begin(), scene.objects.end(),
                     [](const Object& o) { return o.alphaMode == AlphaMode::Blend; });
}

}  // namespace

bool shadesWithoutNoise(const Scene& scene) {
  return scene.render.bounces == 0 && (!scene.environment || scene.environment->method == IblMethod::Prefiltered) &&
         !blends(scene);
}

std::string chooseSampling(Scene& scene) {
  if (scene.render.sampling != Sampling::Chosen) return "";
  if (shadesWithoutNoise(scene)) {
    scene.render.sampling = Sampling::OnePass;
    scene.render.samplesPerPixel = kAntiAliasingSpp;
    return "no light is sampled at random";
  }
  scene.render.sampling = Sampling::Adaptive;
  const bool environmentSampled = scene.environment && scene.environment->method != IblMethod::Prefiltered;
  if (scene.render.bounces == 0)
    return environmentSampled ? "the environment is sampled at random" : "blended surfaces are drawn at random";
  return environmentSampled ? "paths and the environment's samples are random" : "paths are random";
}

}  // namespace facet::scene
