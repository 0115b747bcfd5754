// The Khronos glTF sample models a test can carry (tests/scenes/data/khronos),
// each rendered on both backends and judged by what its README asks a
// person to see on its screenshot, under parity.
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "scenes/scene_file.h"
#include "scenes/studio_environment.h"
#include "tests/support/path_parity.h"

namespace facet {
namespace {

scene::Scene khronosModel(const std::string& name) {
  return scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "khronos" / name / (name + ".gltf"));
}

// The Pearson correlation of two equally long lists.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / double(a.size()), mb += b[i] / double(b.size());
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

// A model seen head-on along -z from `distance` in front of `centre`, lit
// by the studio, and where a point of the plane z = centre.z lands.
struct HeadOn {
  glm::dvec3 centre;
  double distance, fov;
  int size;

  testing::PathRenders render(gpu::Device& device, scene::Scene scene) const {
    scene.camera = {centre + glm::dvec3(0, 0, distance), centre, {0, 1, 0}, fov};
    scene.environment = scene::studioEnvironment();
    scene.render.width = scene.render.height = size;
    scene.render.samplesPerPixel = 4;
    const testing::PathRenders r = testing::renderBoth(device, scene);
    testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-3, .parted = 20});
    return r;
  }
  double pixelsPerUnit() const { return 0.5 * size / (distance * std::tan(fov * std::numbers::pi / 360.0)); }
  glm::ivec2 pixel(double x, double y) const {
    return {int(std::lround(0.5 * size + (x - centre.x) * pixelsPerUnit())),
            int(std::lround(0.5 * size - (y - centre.y) * pixelsPerUnit()))};
  }
};

using KhronosModels = testing::GpuRenderTest;

// TextureTransformMultiTest: each row is one texture input (base colour,
// emission, normal, metal/rough, occlusion, unlit, the coat's strength,
// roughness and normal), its three tiles reading a checkmark through
// TEXCOORD_0 transformed, TEXCOORD_1 transformed, and untransformed
// coordinates of their own (the control). "An implementation should render
// rows of checkmarks, where each of the three tiles in a row look virtually
// identical"; a transform left out shows a crossed-out circle. A normal
// map's tangent frame turns with its slot's transform, or its checkmark is
// lit from another side than the control's.
TEST_F(KhronosModels, TextureTransformsTurnEverySlotAsItsControlShows) {
  const scene::Scene scene = khronosModel("TextureTransformMultiTest");
  EXPECT_TRUE(scene.warnings.empty());
  // Tiles 0.2 wide, columns at x = 0.1, 0.35, 0.6, rows from y = 0.75 down
  // by 0.25, in the plane z = 0.
  const HeadOn view{{0.35, -0.25, 0.0}, 6.0, 24.0, 192};
  const testing::PathRenders r = view.render(device_, scene);
  // A tile's luminances over its central 11 x 11 pixels (0.15 of its 0.2).
  const auto tile = [&](const Image& image, double x, double y) {
    const glm::ivec2 p = view.pixel(x, y);
    std::vector<double> values;
    for (int row = p.y - 5; row <= p.y + 5; ++row)
      for (int column = p.x - 5; column <= p.x + 5; ++column) {
        const glm::vec4 c = image.beauty[std::size_t(row * view.size + column)];
        values.push_back((c.r + c.g + c.b) / 3.0);
      }
    return values;
  };
  const char* rows[] = {"base colour", "emission", "normal",         "metal/rough", "occlusion",
                        "unlit",       "coat",     "coat roughness", "coat normal"};
  for (const Image* image : {&r.reference, &r.gpu.image})
    for (int row = 0; row < 9; ++row) {
      const double y = 0.75 - 0.25 * row;
      const std::vector<double> control = tile(*image, 0.6, y);
      const double first = correlation(tile(*image, 0.1, y), control);
      const double second = correlation(tile(*image, 0.35, y), control);
      std::printf("%s %-14s TEXCOORD_0 %.2f, TEXCOORD_1 %.2f against the control\n",
                  image == &r.reference ? "cpu" : "gpu", rows[row], first, second);
      EXPECT_GT(first, 0.6) << rows[row];
      EXPECT_GT(second, 0.6) << rows[row];
    }
}

// NegativeScaleTest: the second row's checkmarks sit on nodes of negative
// scale, whose winding turns over (glTF 2.0, 3.5.3). Each tile is a
// one-sided sheet with a green checkmark on the side that should show and
// a red X on the other, so a renderer that culls the wrong side shows red.
// Below, each sphere of the -1.0 column is turned inside out and double
// sided: with its normals turned as the winding is, it shades as its
// partner in the 1.0 column.
TEST_F(KhronosModels, NegativeScaleCullsTheBackAndTurnsTheNormals) {
  const scene::Scene scene = khronosModel("NegativeScaleTest");
  EXPECT_TRUE(scene.warnings.empty());
  const HeadOn view{{0.0, 0.0, 0.0}, 15.0, 40.0, 160};
  const testing::PathRenders r = view.render(device_, scene);
  // The mean colour of the square of half side 0.25 about (x, y).
  const auto mean = [&](const Image& image, double x, double y) {
    const glm::ivec2 p = view.pixel(x, y);
    const int half = int(std::lround(0.25 * view.pixelsPerUnit()));
    glm::dvec3 sum(0.0);
    for (int row = p.y - half; row <= p.y + half; ++row)
      for (int column = p.x - half; column <= p.x + half; ++column)
        sum += glm::dvec3(image.beauty[std::size_t(row * view.size + column)]);
    return sum / double((2 * half + 1) * (2 * half + 1));
  };
  for (const Image* image : {&r.reference, &r.gpu.image}) {
    int red = 0, green = 0;
    for (const glm::vec4& c : image->beauty) {
      red += c.r > 0.3f && c.g < 0.5f * c.r && c.b < 0.5f * c.r;
      green += c.g > 0.2f && c.r < 0.5f * c.g && c.b < 0.5f * c.g;
    }
    std::printf("%s: %d red and %d green pixels\n", image == &r.reference ? "cpu" : "gpu", red, green);
    EXPECT_EQ(red, 0);
    EXPECT_GT(green, 100);                  // six checkmarks of about 20 pixels each
    for (double y : {-1.0, -2.25, -3.5}) {  // white, dark blue, metal
      const glm::dvec3 upright = mean(*image, 1.0, y), inverted = mean(*image, 3.0, y);
      std::printf("  spheres at y %.2f: %.4f and %.4f\n", y, upright.g, inverted.g);
      EXPECT_LT(glm::length(upright - inverted), 0.05 * glm::length(upright)) << "y " << y;
    }
  }
}

}  // namespace
}  // namespace facet
