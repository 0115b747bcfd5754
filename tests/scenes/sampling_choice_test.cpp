// The sampling chosen by the scene (scenes/sampling_choice.h): one pass of
// 16 where no light is sampled at random, adaptive rounds where paths, the
// environment's samples or blended surfaces are random, and stated sampling
// kept.
#include "scenes/sampling_choice.h"

#include <gtest/gtest.h>

#include <optional>

#include "scenes/studio_environment.h"

namespace facet::scene {
namespace {

Scene chosen(std::optional<IblMethod> method, int bounces) {
  Scene s;
  s.render.sampling = Sampling::Chosen;
  s.render.bounces = bounces;
  if (method) {
    s.environment = studioEnvironment();
    s.environment->method = *method;
  }
  return s;
}

TEST(SamplingChoice, OnePassWhereNoLightIsSampledAtRandom) {
  for (const std::optional<IblMethod> method : {std::optional<IblMethod>(), std::optional(IblMethod::Prefiltered)}) {
    Scene s = chosen(method, 0);
    EXPECT_TRUE(shadesWithoutNoise(s));
    EXPECT_EQ(chooseSampling(s), "no light is sampled at random");
    EXPECT_EQ(s.render.sampling, Sampling::OnePass);
    EXPECT_EQ(s.render.samplesPerPixel, kAntiAliasingSpp);
  }
}

TEST(SamplingChoice, AdaptiveRoundsWhereAnythingIsRandom) {
  for (const IblMethod method : {IblMethod::Sampled, IblMethod::Filtered}) {
    Scene s = chosen(method, 0);
    EXPECT_FALSE(shadesWithoutNoise(s));
    EXPECT_EQ(chooseSampling(s), "the environment is sampled at random");
    EXPECT_EQ(s.render.sampling, Sampling::Adaptive);
  }
  Scene paths = chosen(IblMethod::Sampled, 12);
  EXPECT_EQ(chooseSampling(paths), "paths and the environment's samples are random");
  EXPECT_EQ(paths.render.sampling, Sampling::Adaptive);
  Scene lampsOnly = chosen(std::nullopt, 12);
  EXPECT_EQ(chooseSampling(lampsOnly), "paths are random");
  EXPECT_EQ(lampsOnly.render.sampling, Sampling::Adaptive);
  // glTF's BLEND draws each ray's pass at random; MASK decides it.
  for (const AlphaMode mode : {AlphaMode::Mask, AlphaMode::Blend}) {
    Scene cutout = chosen(IblMethod::Prefiltered, 0);
    cutout.objects.emplace_back().alphaMode = mode;
    EXPECT_EQ(shadesWithoutNoise(cutout), mode == AlphaMode::Mask);
    EXPECT_EQ(chooseSampling(cutout),
              mode == AlphaMode::Mask ? "no light is sampled at random" : "blended surfaces are drawn at random");
  }
}

TEST(SamplingChoice, StatedSamplingIsKept) {
  for (const Sampling stated : {Sampling::OnePass, Sampling::Adaptive}) {
    Scene s = chosen(IblMethod::Sampled, 12);
    s.render.sampling = stated;
    s.render.samplesPerPixel = 4;
    EXPECT_EQ(chooseSampling(s), "");
    EXPECT_EQ(s.render.sampling, stated);
    EXPECT_EQ(s.render.samplesPerPixel, 4);
  }
}

}  // namespace
}  // namespace facet::scene
