// glTF COLOR_0 and TEXCOORD_1 on both backends: a quad whose corners are
// red, green, blue and white shows those hues at its corners and their mix
// (grey) at its centre, as authored and subdivided; a base colour texture on
// TEXCOORD_1, which mirrors u, puts its marker where TEXCOORD_1 says. Each
// within the tolerances of analysis/parity.h.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <random>
#include <string>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/channels_gltf.h"
#include "tests/support/gpu_device.h"
#include "tests/support/textured_gltf.h"

namespace facet {
namespace {

class ChannelParity : public gpu::testing::GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    dir_ = std::filesystem::temp_directory_path() / ("facet_channel_parity_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::filesystem::remove_all(dir_);
    GpuTest::TearDown();
  }

  // The scene rendered by both backends, which must agree; the CPU's image.
  Image renderBoth(scene::Scene& scene, scene::IntersectionMethod method = scene::IntersectionMethod::Exact) {
    scene.render.width = 64;
    scene.render.height = 48;
    scene.render.method = method;
    const scene::SceneGeometry geometry = scene::buildGeometry(scene);
    Image reference = cpu::renderReference(scene, geometry);
    gpu_backend::GpuRenderer renderer(device_);
    gpu_ = renderer.render(scene, geometry).image;
    const analysis::ParityReport parity = analysis::compareImages(reference, gpu_);
    EXPECT_TRUE(parity.pass) << analysis::describe(parity);
    EXPECT_GT(parity.covered, 1000u);
    return reference;
  }

  std::filesystem::path dir_;
  Image gpu_;
};

// The RGB of the covered pixel whose surface point lies nearest `target`;
// the mean of those that tie to float rounding (pixels placed symmetrically
// about it), so that the choice does not rest on the rounding.
glm::vec3 colourAt(const Image& image, glm::vec3 target) {
  float nearest = std::numeric_limits<float>::infinity();
  for (std::size_t p = 0; p < image.beauty.size(); ++p)
    if (image.beauty[p].a > 0.0f) nearest = std::min(nearest, glm::distance(image.position[p], target));
  EXPECT_LT(nearest, 0.1f);
  glm::vec3 sum(0.0f);
  int ties = 0;
  for (std::size_t p = 0; p < image.beauty.size(); ++p)
    if (image.beauty[p].a > 0.0f && glm::distance(image.position[p], target) <= nearest * 1.0001f + 1e-6f) {
      sum += glm::vec3(image.beauty[p]);
      ++ties;
    }
  return sum / float(ties);
}

// Red, green or blue (channel 0, 1, 2) well above the other two.
bool dominant(glm::vec3 c, int channel) {
  for (int other = 0; other < 3; ++other)
    if (other != channel && !(c[channel] > 3.0f * c[other])) return false;
  return true;
}

void expectCornerHues(const Image& image) {
  EXPECT_TRUE(dominant(colourAt(image, {-0.9f, -0.9f, 0.0f}), 0));
  EXPECT_TRUE(dominant(colourAt(image, {0.9f, -0.9f, 0.0f}), 1));
  EXPECT_TRUE(dominant(colourAt(image, {0.9f, 0.9f, 0.0f}), 2));
  // White: grey.
  const glm::vec3 white = colourAt(image, {-0.9f, 0.9f, 0.0f});
  EXPECT_GT(std::min({white.r, white.g, white.b}), 0.9f * std::max({white.r, white.g, white.b}));
  // The centre lies on the diagonal the two triangles share, from red to
  // blue: half of each, no green.
  const glm::vec3 centre = colourAt(image, {0.0f, 0.0f, 0.0f});
  EXPECT_NEAR(centre.r / centre.b, 1.0f, 0.05f);
  EXPECT_LT(centre.g, 0.1f * centre.r);
}

TEST_F(ChannelParity, VertexColoursMultiplyTheBaseColourAsAuthored) {
  const nlohmann::json attributes = {{"POSITION", 0}, {"COLOR_0", 4}};
  scene::Scene scene = scene::loadScene(facet::testing::writeChannelQuad(dir_, "colours", attributes, {}));
  const Image cpu = renderBoth(scene);
  expectCornerHues(cpu);
  expectCornerHues(gpu_);
  // Across each triangle's patches: the bottom edge runs from red to
  // green, half and half at its middle, with little of the blue corner.
  const glm::vec3 middle = colourAt(cpu, {0.0f, -0.95f, 0.0f});
  EXPECT_NEAR(middle.r / middle.g, 1.0f, 0.2f);
  EXPECT_LT(middle.b, 0.2f * middle.r) << middle.r << " " << middle.g << " " << middle.b;
}

TEST_F(ChannelParity, VertexColoursSubdivideSmoothly) {
  const nlohmann::json attributes = {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"COLOR_0", 3}};
  scene::Scene scene = scene::loadScene(facet::testing::writeChannelQuad(dir_, "smooth", attributes, {}));
  // Sharp corners keep the limit surface out to the quad's corners.
  for (scene::Object& object : scene.objects) {
    object.subdivision = scene::Subdivision::CatmullClark;
    for (int v = 0; v < object.cage.vertexCount(); ++v) object.cage.corners.push_back({v, 10.0f});
  }
  const Image cpu = renderBoth(scene);
  expectCornerHues(cpu);
  expectCornerHues(gpu_);
  // Along the bottom edge red falls and green rises, step by step.
  glm::vec3 previous = colourAt(cpu, {-0.7f, -0.8f, 0.0f});
  for (float x = -0.5f; x <= 0.71f; x += 0.2f) {
    const glm::vec3 c = colourAt(cpu, {x, -0.8f, 0.0f});
    EXPECT_LT(c.r, previous.r) << x;
    EXPECT_GT(c.g, previous.g) << x;
    previous = c;
  }
}

TEST_F(ChannelParity, ABaseColourTextureOnTheSecondSetFollowsIt) {
  // Left half red, right half blue.
  std::vector<facet::testing::Rgba8> texels;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      texels.push_back(x < 4 ? facet::testing::Rgba8{230, 10, 10, 255} : facet::testing::Rgba8{10, 10, 230, 255});
  ASSERT_TRUE(facet::testing::writePng(dir_ / "marker.png", 8, 8, texels));
  const auto file = [&](int set) {
    const nlohmann::json parts = {
        {"images", {{{"uri", "marker.png"}}}},
        {"textures", {{{"source", 0}}}},
        {"materials",
         {{{"doubleSided", true},
           {"pbrMetallicRoughness",
            {{"metallicFactor", 0.0}, {"baseColorTexture", {{"index", 0}, {"texCoord", set}}}}}}}}};
    return facet::testing::writeChannelQuad(dir_, "set" + std::to_string(set),
                                            {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 2}}, parts);
  };
  scene::Scene second = scene::loadScene(file(1));
  const Image cpu = renderBoth(second);
  for (const Image* image : {&cpu, static_cast<const Image*>(&gpu_)}) {
    // TEXCOORD_1 mirrors u: the image's right half (blue) lies on the quad's left.
    EXPECT_TRUE(dominant(colourAt(*image, {-0.5f, 0.0f, 0.0f}), 2));
    EXPECT_TRUE(dominant(colourAt(*image, {0.5f, 0.0f, 0.0f}), 0));
  }
  // The same file on TEXCOORD_0 puts the marker the other way round.
  scene::Scene first = scene::loadScene(file(0));
  first.render.width = 64;
  first.render.height = 48;
  const Image firstImage = cpu::renderReference(first, scene::buildGeometry(first));
  EXPECT_TRUE(dominant(colourAt(firstImage, {-0.5f, 0.0f, 0.0f}), 0));
  EXPECT_TRUE(dominant(colourAt(firstImage, {0.5f, 0.0f, 0.0f}), 2));
}

}  // namespace
}  // namespace facet
