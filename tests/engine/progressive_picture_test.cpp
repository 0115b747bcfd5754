// A progressive picture on the CPU reference: each pass adds the scene's
// samples with random numbers of its own; a 1-spp picture's first pass is a
// quick look that its refining passes replace; the first pass is whole
// whatever `stale` says; a new first pass starts the picture anew.
#include "engine/progressive_picture.h"

#include <gtest/gtest.h>

#include <memory>

#include "tests/support/blob_scene.h"
#include "tests/support/environment_maps.h"

namespace facet {
namespace {

scene::Scene blob(int spp) {
  scene::Scene s = testing::blobUnder(
      testing::lambertian(0.5),
      std::make_shared<const scene::EnvironmentMap>(ibl::testing::mapOf(
          16, 8, [](glm::dvec3 d) { return glm::dvec3(d.y > 0.5 ? 4.0 : 0.2); })),
      8);
  s.render.samplesPerPixel = spp;
  return s;
}

const auto neverStale = [] { return false; };

TEST(ProgressivePicture, EachPassAddsTheScenesSamplesWithNumbersOfItsOwn) {
  Renderer renderer;
  ProgressivePicture picture(renderer, Backend::Cpu, 1);
  const scene::Scene scene = blob(4);
  ASSERT_TRUE(picture.render(scene, 0, neverStale));
  const Image first = picture.image();
  EXPECT_EQ(picture.passes(), 1);
  EXPECT_EQ(picture.samples(), 4);
  EXPECT_EQ(first.width, 8);
  EXPECT_EQ(first.height, 8);
  const std::optional<ProgressivePicture::Pass> second = picture.render(scene, 1, neverStale);
  ASSERT_TRUE(second);
  EXPECT_FALSE(second->geometryDiced) << "the CPU reference keeps nothing between renders";
  EXPECT_EQ(picture.passes(), 2);
  EXPECT_EQ(picture.samples(), 8);
  EXPECT_NE(picture.image().beauty, first.beauty) << "the second pass's samples are not the first's";
  EXPECT_EQ(picture.image().depth, first.depth) << "the AOVs are the first pass's";
}

TEST(ProgressivePicture, AOneSampleFirstPassIsAQuickLookTheRefiningPassesReplace) {
  Renderer renderer;
  ProgressivePicture picture(renderer, Backend::Cpu, 1);
  const scene::Scene scene = blob(1);
  ASSERT_TRUE(picture.render(scene, 0, neverStale));
  EXPECT_EQ(picture.samples(), 1);
  ASSERT_TRUE(picture.render(scene, 1, neverStale));
  EXPECT_EQ(picture.samples(), 4) << "a net of 4, the quick look not in the mean";
  ASSERT_TRUE(picture.render(scene, 2, neverStale));
  EXPECT_EQ(picture.samples(), 8);
  EXPECT_EQ(picture.passes(), 3);
}

TEST(ProgressivePicture, TheFirstPassIsWholeAndStartsThePictureAnew) {
  Renderer renderer;
  ProgressivePicture picture(renderer, Backend::Cpu, 1);
  const scene::Scene scene = blob(4);
  const auto alwaysStale = [] { return true; };
  ASSERT_TRUE(picture.render(scene, 0, alwaysStale)) << "nothing to keep yet: the first pass is never cut";
  ASSERT_TRUE(picture.render(scene, 1, neverStale));
  const Image fresh = [&] {
    ProgressivePicture other(renderer, Backend::Cpu, 1);
    other.render(scene, 0, neverStale);
    return other.image();
  }();
  ASSERT_TRUE(picture.render(scene, 0, neverStale));
  EXPECT_EQ(picture.passes(), 1);
  EXPECT_EQ(picture.samples(), 4);
  EXPECT_EQ(picture.image().beauty, fresh.beauty);
}

}  // namespace
}  // namespace facet
