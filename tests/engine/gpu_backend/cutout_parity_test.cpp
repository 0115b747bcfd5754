// glTF's alphaMode MASK and BLEND on both backends (docs/rendering.md,
// "Cutouts" and "Blending"): a quad whose base colour texture is a checker
// of opaque and clear cells, in front of a lit backdrop, lit straight from
// the front. With MASK, where a pixel's centre ray meets a clear cell it goes
// on to the backdrop; the backdrop is in shadow exactly behind the opaque
// cells, so the quad's shadow has holes. The base colour factor's alpha
// scales the texture's. With BLEND, the cells of alpha a cover a of what lies
// behind them and pass 1 - a of the light, on average over a pixel's samples.
// Each render is checked on both backends, and the two against each other.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "analysis/parity.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "scenes/environment_map.h"
#include "scenes/scene_file.h"
#include "scenes/scene_geometry.h"
#include "tests/support/cages.h"
#include "tests/support/gpu_device.h"
#include "tests/support/path_parity.h"
#include "tests/support/textured_gltf.h"

namespace facet {
namespace {

constexpr int kCells = 4;  // the checker's cells a side; cell (0, 0), at the top left, is opaque
// The camera, three units in front of the quad, looking straight at it; off
// its axis, so that no pixel's ray meets the quad exactly on the edge its
// triangles share (the GPU's float triangles may let such a ray through).
const glm::dvec3 kEye(0.0123, 0.0071, 3.0);

// Whether the checker is opaque at quad point (x, y) (the quad spans
// [-1, 1]^2, texture coordinate (0, 0) at (-1, 1)); unset within `margin`
// of a cell's edge, where the texture's filter blends the two.
std::optional<bool> opaqueAt(double x, double y, double margin = 0.05) {
  const double u = 0.5 * (x + 1.0) * kCells, v = 0.5 * (1.0 - y) * kCells;
  if (u < 0 || v < 0 || u >= kCells || v >= kCells) return std::nullopt;
  const double fu = u - std::floor(u), fv = v - std::floor(v);
  if (std::min({fu, 1.0 - fu, fv, 1.0 - fv}) * 2.0 / kCells < margin) return std::nullopt;
  return (int(u) + int(v)) % 2 == 0;
}

class Cutout : public gpu::testing::GpuTest, public ::testing::WithParamInterface<scene::IntersectionMethod> {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    dir_ = std::filesystem::temp_directory_path() / ("facet_cutout_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
    facet::testing::writePng(dir_ / "checker.png", 32, 32,
                             facet::testing::checkerTexels(32, kCells, {255, 255, 255, 255}, {255, 255, 255, 0}));
  }
  void TearDown() override {
    renderer_.reset();
    std::filesystem::remove_all(dir_);
    GpuTest::TearDown();
  }

  // The checker quad of `alphaMode`, `factor` its base colour factor's
  // alpha, one unit in front of a grey backdrop facing it, seen and lit
  // from the front.
  scene::Scene makeScene(const std::string& name, const std::string& alphaMode, double factor) {
    const nlohmann::json material = {{"doubleSided", true},
                                     {"alphaMode", alphaMode},
                                     {"pbrMetallicRoughness",
                                      {{"baseColorFactor", {0.1, 0.1, 0.1, factor}},
                                       {"metallicFactor", 0.0},
                                       {"baseColorTexture", {{"index", 0}}}}}};
    scene::Scene s = scene::loadScene(facet::testing::writeTexturedQuad(
        dir_, name,
        {{"materials", {material}}, {"textures", {{{"source", 0}}}}, {"images", {{{"uri", "checker.png"}}}}}));
    scene::Object backdrop;
    backdrop.name = "backdrop";
    backdrop.cage = scene::testing::singleFace({{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}});
    backdrop.subdivision = scene::Subdivision::None;
    backdrop.material = int(s.materials.size());
    s.materials.emplace_back().diffuse = glm::dvec3(0.8);
    s.objects.push_back(backdrop);
    s.camera = {kEye, kEye - glm::dvec3(0.0, 0.0, 3.0), {0.0, 1.0, 0.0}, 45.0};
    s.lights = {{scene::LightType::Directional, glm::dvec3(1.0), glm::dvec3(0.0), {0.0, 0.0, -1.0}}};
    s.environment.reset();  // the light alone: a shadowed point is black
    s.render.width = s.render.height = 32;
    s.render.method = GetParam();
    // Micro-triangles interpolate the patch's (s, t), so the texture they
    // read strays from the limit surface's by the square of their size: fine
    // ones keep the cells where the positions say.
    s.render.tessellationRate = 12;
    return s;
  }

  // Both backends' renders of `scene`, which must agree.
  std::pair<Image, Image> renderBoth(const scene::Scene& scene) {
    const scene::SceneGeometry geometry = scene::buildGeometry(scene);
    Image reference = cpu::renderReference(scene, geometry);
    if (!renderer_) renderer_ = std::make_unique<gpu_backend::GpuRenderer>(device_);
    Image gpu = renderer_->render(scene, geometry).image;
    const analysis::ParityReport parity = analysis::compareImages(reference, gpu);
    EXPECT_TRUE(parity.pass) << analysis::describe(parity);
    return {std::move(reference), std::move(gpu)};
  }

  std::filesystem::path dir_;
  std::unique_ptr<gpu_backend::GpuRenderer> renderer_;
};

// Pixels whose centre ray met the quad (z = 0) and the backdrop (z = -1).
struct Seen {
  int quad = 0, throughHoles = 0, shadowed = 0, litThroughHoles = 0;
};

Seen checkCutout(const Image& image, bool quadPresent) {
  Seen seen;
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    const glm::dvec3 p = image.position[i];
    if (std::abs(p.z) < 1e-3) {
      ++seen.quad;
      EXPECT_TRUE(quadPresent);
      EXPECT_NE(opaqueAt(p.x, p.y), std::optional(false)) << "quad seen in a clear cell at " << p.x << ", " << p.y;
      continue;
    }
    if (std::abs(p.z + 1.0) > 1e-3) continue;
    // Where the centre ray crossed the quad's plane on its way, and which
    // cell lies straight in front of the point (the light's direction).
    const glm::dvec3 crossing = kEye + (p - kEye) * (3.0 / 4.0);
    // The beauty's sample may fall anywhere in the pixel (0.05 on the
    // backdrop from its centre), the AOVs' ray passes through its centre.
    const std::optional<bool> passed = opaqueAt(crossing.x, crossing.y), front = opaqueAt(p.x, p.y, 0.09);
    if (quadPresent && passed) {
      EXPECT_FALSE(*passed) << "backdrop seen through an opaque cell at " << crossing.x << ", " << crossing.y;
      ++seen.throughHoles;
    }
    if (!front) continue;
    const bool shadowed = quadPresent && *front;
    if (shadowed) {
      EXPECT_LT(image.beauty[i].r, 1e-6f) << "lit behind an opaque cell at " << p.x << ", " << p.y;
      ++seen.shadowed;
    } else {
      EXPECT_GT(image.beauty[i].r, 0.1f) << "shadowed behind a clear cell at " << p.x << ", " << p.y;
      if (quadPresent) ++seen.litThroughHoles;
    }
  }
  return seen;
}

TEST_P(Cutout, ClearCellsLetRaysAndLightThrough) {
  const auto [reference, gpu] = renderBoth(makeScene("mask", "MASK", 1.0));
  for (const Image* image : {&reference, &gpu}) {
    SCOPED_TRACE(image == &reference ? "CPU" : "GPU");
    const Seen seen = checkCutout(*image, true);
    EXPECT_GT(seen.quad, 50);
    EXPECT_GT(seen.throughHoles, 20);
    EXPECT_GT(seen.litThroughHoles, 10);
  }
}

TEST_P(Cutout, TheFactorScalesTheAlpha) {
  // 0.4 x 1 is below the cutoff everywhere: the quad is gone, and its shadow.
  const auto [faintReference, faintGpu] = renderBoth(makeScene("faint", "MASK", 0.4));
  for (const Image* image : {&faintReference, &faintGpu}) EXPECT_EQ(checkCutout(*image, false).quad, 0);
}

// The mean radiance of the pixels whose centre ray crosses the quad's plane
// in a cell of opacity `crossing` and whose backdrop point lies behind a
// cell of opacity `front`, with their count.
std::pair<double, int> meanOver(const Image& image, bool crossing, bool front) {
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    const glm::dvec3 p = image.position[i];
    const double depth = kEye.z - p.z;  // 3 on the quad, 4 on the backdrop
    if (std::abs(depth - 3.0) > 1e-3 && std::abs(depth - 4.0) > 1e-3) continue;
    const glm::dvec3 onQuad = kEye + (p - kEye) * (3.0 / depth), onBackdrop = kEye + (p - kEye) * (4.0 / depth);
    if (opaqueAt(onQuad.x, onQuad.y) != std::optional(crossing) ||
        opaqueAt(onBackdrop.x, onBackdrop.y, 0.09) != std::optional(front))
      continue;
    sum += image.beauty[i].r;
    ++count;
  }
  return {count ? sum / count : 0.0, count};
}

TEST_P(Cutout, BlendCoversAlphaOfWhatLiesBehindAndPassesTheRestOfTheLight) {
  // The quad's and the lit backdrop's radiance, from the quad cut out.
  const auto [maskReference, maskGpu] = renderBoth(makeScene("mask", "MASK", 1.0));
  const double quad = meanOver(maskReference, true, true).first, backdrop = meanOver(maskReference, false, false).first;
  ASSERT_GT(backdrop, 0.1);
  constexpr double kAlpha = 0.3;
  scene::Scene blended = makeScene("blend", "BLEND", kAlpha);
  blended.render.samplesPerPixel = 64;
  const auto [reference, gpu] = renderBoth(blended);
  for (const Image* image : {&reference, &gpu}) {
    SCOPED_TRACE(image == &reference ? "CPU" : "GPU");
    // Behind a cell of alpha 0.3 the camera sees the quad in 30% of its
    // samples, and the backdrop lit by the 70% of shadow rays that pass.
    const auto [covered, coveredPixels] = meanOver(*image, true, true);
    std::printf("behind alpha %.1f: %.4f over %d pixels (quad %.4f, backdrop %.4f)\n", kAlpha, covered, coveredPixels,
                quad, backdrop);
    EXPECT_GT(coveredPixels, 40);
    EXPECT_NEAR(covered, kAlpha * quad + (1 - kAlpha) * (1 - kAlpha) * backdrop, 0.03 * backdrop);
    // A clear cell, alpha 0, is never there.
    const auto [clear, clearPixels] = meanOver(*image, false, false);
    EXPECT_GT(clearPixels, 40);
    EXPECT_NEAR(clear, backdrop, 1e-2 * backdrop);
  }
}

TEST_P(Cutout, BlendedPathsPassThroughAsTheCpuReferencesDo) {
  // Light the backdrop bounces back meets the quad's back and passes as the
  // camera's rays and the shadow rays do, decided alike on both backends;
  // a sampled environment adds shadow rays of both techniques, keyed by the
  // seed of their vertex.
  scene::Scene blended = makeScene("blend", "BLEND", 0.5);
  blended.render.samplesPerPixel = 4;
  blended.render.bounces = 3;
  blended.environment.emplace();
  blended.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(0.5)));
  blended.environment->method = scene::IblMethod::Sampled;
  blended.environment->samples = 2;
  blended.environment->seed = 11;
  facet::testing::expectPathParity(facet::testing::renderBoth(device_, blended),
                                   {.median = 1e-4, .p98 = 2e-3, .parted = 8});
}

INSTANTIATE_TEST_SUITE_P(Methods, Cutout,
                         ::testing::Values(scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated),
                         facet::testing::methodName);

}  // namespace
}  // namespace facet
