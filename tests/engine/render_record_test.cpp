// What a render's outputs record of its sampling: one pass of its samples,
// or adaptive rounds with their threshold and cap, and a digest that tells
// the two apart so that `facet merge` never joins their tiles.
#include "engine/render_record.h"

#include <gtest/gtest.h>

#include <string>

namespace facet {
namespace {

scene::Scene sampled(scene::Sampling sampling) {
  scene::Scene s;
  s.render.width = 64;
  s.render.height = 48;
  s.render.samplesPerPixel = 4;
  s.render.sampling = sampling;
  return s;
}

TEST(RenderRecord, OnePassRecordsItsSamples) {
  const std::string text = renderSettingsText(sampled(scene::Sampling::OnePass), "cpu");
  EXPECT_EQ(text.rfind("backend=cpu size=64x48 spp=4 method=exact", 0), 0u) << text;
  EXPECT_EQ(text.find("adaptive"), std::string::npos) << text;
}

TEST(RenderRecord, AdaptiveRoundsRecordTheirThresholdAndCap) {
  scene::Scene s = sampled(scene::Sampling::Adaptive);
  s.render.noiseThreshold = 0.01;
  s.render.maxSamplesPerPixel = 1024;
  const std::string text = renderSettingsText(s, "gpu");
  EXPECT_EQ(text.rfind("backend=gpu size=64x48 sampling=adaptive noiseThreshold=0.01 maxSpp=1024 method=exact", 0), 0u)
      << text;
  EXPECT_EQ(text.find("spp="), std::string::npos) << "the rounds' own samples are not the picture's: " << text;
}

TEST(RenderRecord, TheDigestTellsOnePassFromRoundsAndOneThresholdFromAnother) {
  const scene::Scene pass = sampled(scene::Sampling::OnePass), rounds = sampled(scene::Sampling::Adaptive);
  scene::Scene tighter = rounds;
  tighter.render.noiseThreshold = 0.01;
  scene::Scene more = rounds;
  more.render.maxSamplesPerPixel = 1024;
  EXPECT_NE(settingsDigest(pass, "cpu"), settingsDigest(rounds, "cpu"));
  EXPECT_NE(settingsDigest(rounds, "cpu"), settingsDigest(tighter, "cpu"));
  EXPECT_NE(settingsDigest(rounds, "cpu"), settingsDigest(more, "cpu"));
  EXPECT_NE(settingsDigest(rounds, "cpu"), settingsDigest(sampled(scene::Sampling::Chosen), "cpu"));
  EXPECT_EQ(settingsDigest(rounds, "cpu"), settingsDigest(sampled(scene::Sampling::Adaptive), "cpu"));
}

}  // namespace
}  // namespace facet
