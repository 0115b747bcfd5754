#include "scenes/sampling_choice.h"

namespace facet::scene {

bool shadesWithoutNoise(const Scene& scene) {
  return scene.render.bounces == 0 && (!scene.environment || scene.environment->method == IblMethod::Prefiltered);
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
  if (scene.render.bounces == 0) return "the environment is sampled at random";
  return environmentSampled ? "paths and the environment's samples are random" : "paths are random";
}

}  // namespace facet::scene
