// Textures in the CPU reference: mip levels chosen from the ray cone keep a
// minified checker from aliasing. Each 1-sample render is held against a
// supersampled one without mips (the checker's true pixel averages); the
// mipmapped render must have the smaller error. BENCHMARKS.md has the
// numbers at a larger size.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "engine/cpu/reference_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/temp_dir.h"
#include "tests/support/textured_scenes.h"

namespace facet {
namespace {

constexpr int kNoMips = 9729;     // glTF LINEAR
constexpr int kTrilinear = 9987;  // glTF LINEAR_MIPMAP_LINEAR

class TextureAliasing : public facet::testing::TempDirTest {
 protected:
  // The beauty of the checker repeated 16 times across the quad (128 squares
  // a side) at `spp` samples per pixel.
  Image render(int minFilter, int spp) {
    const std::string name = "quad_" + std::to_string(minFilter) + "_" + std::to_string(spp);
    scene::Scene scene = scene::loadScene(facet::testing::writeTexturedScene(dir_, name, 8, 16.0, minFilter));
    scene.render.width = 32;
    scene.render.height = 24;
    scene.render.samplesPerPixel = spp;
    return cpu::renderReference(scene, scene::buildGeometry(scene));
  }
};

// Root-mean-square difference of the beauty's RGB over pixels both cover fully.
double rmsError(const Image& image, const Image& truth) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < truth.beauty.size(); ++p) {
    if (truth.beauty[p].a < 1.0f || image.beauty[p].a < 1.0f) continue;
    for (int c = 0; c < 3; ++c) sum += std::pow(double(image.beauty[p][c]) - double(truth.beauty[p][c]), 2.0);
    ++count;
  }
  EXPECT_GT(count, 200u);
  return std::sqrt(sum / double(3 * count));
}

TEST_F(TextureAliasing, MipsFromTheRayConeHaveTheSmallerError) {
  const Image truth = render(kNoMips, 64);
  const double withMips = rmsError(render(kTrilinear, 1), truth);
  const double withoutMips = rmsError(render(kNoMips, 1), truth);
  RecordProperty("rms_with_mips", std::to_string(withMips));
  RecordProperty("rms_without_mips", std::to_string(withoutMips));
  EXPECT_LT(withMips, 0.5 * withoutMips) << withMips << " vs " << withoutMips;
}

}  // namespace
}  // namespace facet
