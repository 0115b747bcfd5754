// The GPU backend held to the CPU reference on small images: every example
// scene and every torture cage, both intersection methods, within the
// tolerances of analysis/parity.h.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "tests/support/translate_scene.h"
#include "engine/cpu/reference_renderer.h"
#include "engine/gpu_backend/gpu_renderer.h"
#include "analysis/parity.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/gpu_device.h"
#include "tests/support/path_parity.h"
#include "scenes/environment_map.h"
#include "scenes/scene_file.h"
#include "scenes/input_error.h"
#include "scenes/scene_geometry.h"
#include "scenes/studio_environment.h"

namespace facet {
namespace {

using analysis::compareImages;
using analysis::describe;
using analysis::ParityReport;

struct ParityCase {
  std::filesystem::path file;
  scene::IntersectionMethod method;
  int samplesPerPixel = 1;
  // The file's own subdivision when empty, else what --subdivision would set.
  std::string subdivision;
  int width = 64, height = 48;
};

void PrintTo(const ParityCase& c, std::ostream* out) {
  *out << c.file.filename().string() << (c.method == scene::IntersectionMethod::Exact ? " exact" : " tessellated")
       << ", " << c.samplesPerPixel << " spp";
}

std::string caseName(const ::testing::TestParamInfo<ParityCase>& info) {
  std::string name = info.param.file.stem().string() + "_" +
                     (info.param.method == scene::IntersectionMethod::Exact ? "exact" : "tess") + "_spp" +
                     std::to_string(info.param.samplesPerPixel);
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

std::vector<ParityCase> everyScene() {
  std::vector<std::filesystem::path> files = {std::filesystem::path(FACET_EXAMPLES_DIR) / "preview.json",
                                              std::filesystem::path(FACET_EXAMPLES_DIR) / "gold_cube.gltf",
                                              std::filesystem::path(FACET_TEST_DATA_DIR) / "smooth_gem.gltf"};
  std::vector<std::filesystem::path> cages;
  for (const auto& entry : std::filesystem::directory_iterator(FACET_CAGE_DIR))
    if (entry.path().extension() == ".obj") cages.push_back(entry.path());
  std::sort(cages.begin(), cages.end());
  files.insert(files.end(), cages.begin(), cages.end());
  std::vector<ParityCase> cases;
  for (auto method : {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated}) {
    for (const auto& file : files) cases.push_back({file, method});
    cases.push_back(
        {std::filesystem::path(FACET_EXAMPLES_DIR) / "textured" / "cushion.gltf", method, 1, "catmull-clark"});
  }
  return cases;
}

class GpuParity : public gpu::testing::GpuTest, public ::testing::WithParamInterface<ParityCase> {};

TEST_P(GpuParity, MatchesTheCpuReferenceWithinTolerance) {
  scene::Scene scene = scene::loadScene(GetParam().file);
  if (!GetParam().subdivision.empty()) scene::overrideSubdivision(scene, GetParam().subdivision, "subdivision");
  scene.render.width = GetParam().width;
  scene.render.height = GetParam().height;
  scene.render.method = GetParam().method;
  scene.render.samplesPerPixel = GetParam().samplesPerPixel;
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  cpu::ReferenceStatistics cpuRays;
  const Image reference = cpu::renderReference(scene, geometry, &cpuRays);

  gpu_backend::GpuRenderer renderer(device_);
  const gpu_backend::GpuRenderResult gpu = renderer.render(scene, geometry);
  const ParityReport parity = compareImages(reference, gpu.image);

  EXPECT_TRUE(parity.pass) << describe(parity);
  // A blank frame would compare equal: each scene must show something.
  EXPECT_GT(parity.covered, 50u);
  EXPECT_EQ(gpu.primaryRays, cpuRays.primaryRays);
  // Lights skipped below the horizon may differ where n.l rounds across 0.
  EXPECT_NEAR(double(gpu.shadowRays), double(cpuRays.shadowRays), 1e-3 * double(cpuRays.shadowRays) + 2);
}

INSTANTIATE_TEST_SUITE_P(EveryScene, GpuParity, ::testing::ValuesIn(everyScene()), caseName);

// OpenSubdiv's regression shapes (tests/scenes/data/opensubdiv) where float
// or the reference parted from the truth, at the size where each did
// (docs/parity.md, "OpenSubdiv's shapes"): rays along the edges of patches
// (exact) and of micro-triangles (tessellated); patches far smaller than
// their distance from the eye, at a pole of valence 360 and on the car,
// whose normals float control points relative to the eye turned by up to
// 6.6e-3; and twisted pieces the reference crossed at their far side (a
// crease's patch, and a saddle as authored).
std::vector<ParityCase> openSubdivShapes() {
  std::vector<ParityCase> cases;
  auto add = [&](const char* shape, scene::IntersectionMethod method, const char* subdivision = "") {
    cases.push_back({std::filesystem::path(FACET_TEST_DATA_DIR) / "opensubdiv" / (std::string(shape) + ".obj"), method,
                     1, subdivision, 128, 128});
  };
  for (const char* shape :
       {"loop_nonman_verts", "loop_cube", "loop_icos_semisharp", "catmark_nonman_quadpole360", "catmark_car"}) {
    add(shape, scene::IntersectionMethod::Exact);
    add(shape, scene::IntersectionMethod::Tessellated);
  }
  add("catmark_inf_crease0", scene::IntersectionMethod::Exact);
  add("bilinear_nonplanar", scene::IntersectionMethod::Exact, "none");
  return cases;
}

INSTANTIATE_TEST_SUITE_P(OpenSubdivShapes, GpuParity, ::testing::ValuesIn(openSubdivShapes()), caseName);

// Stratified samples: fractional coverage at silhouettes, and the centre ray
// traced on its own for the AOVs.
INSTANTIATE_TEST_SUITE_P(Supersampled, GpuParity,
                         ::testing::Values(ParityCase{std::filesystem::path(FACET_CAGE_DIR) / "creased_box.obj",
                                                      scene::IntersectionMethod::Exact, 4},
                                           ParityCase{std::filesystem::path(FACET_CAGE_DIR) / "creased_box.obj",
                                                      scene::IntersectionMethod::Tessellated, 4}),
                         caseName);

// The GPU's image of `scene` against the CPU reference's, which must show
// something (a blank frame would compare equal); returns the GPU's.
Image expectParity(gpu::Device& device, const scene::Scene& scene) {
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const Image reference = cpu::renderReference(scene, geometry);
  gpu_backend::GpuRenderer renderer(device);
  Image gpu = renderer.render(scene, geometry).image;
  const ParityReport parity = compareImages(reference, gpu);
  EXPECT_TRUE(parity.pass) << describe(parity);
  EXPECT_GT(parity.covered, 50u);
  return gpu;
}

// A fully rough lobe reads the prefiltered environment about the normal
// itself: on a floor facing exactly +Y, the map's pole, whose longitude
// both backends must take alike (GLSL leaves atan(0, 0) undefined).
class EnvironmentPole : public gpu::testing::GpuTest {};

TEST_F(EnvironmentPole, AFullyRoughFloorFacingUpReadsItAsTheCpuReferenceDoes) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "rough_metal_floor.gltf");
  ASSERT_EQ(scene.materials.front().alpha, 1.0);
  scene.environment = scene::studioEnvironment();
  scene.camera.eye = {0.3, 2.0, 3.0};
  scene.camera.target = {0.0, 0.0, 0.0};
  scene.render.width = 64;
  scene.render.height = 48;
  expectParity(device_, scene);
}

// Precise anywhere: the GPU works relative to the eye, so a scene far from
// the world origin holds the same tolerances as one at it, as far as the
// CPU reference (double) holds.
struct FarCase {
  std::string cage;
  scene::IntersectionMethod method;
  double distance;
};

void PrintTo(const FarCase& c, std::ostream* out) {
  *out << c.cage << (c.method == scene::IntersectionMethod::Exact ? " exact" : " tessellated") << " at " << c.distance;
}

class FarFromTheOrigin : public gpu::testing::GpuTest, public ::testing::WithParamInterface<FarCase> {};

TEST_P(FarFromTheOrigin, MatchesTheCpuReferenceWithinTolerance) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / (GetParam().cage + ".obj"));
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.method = GetParam().method;
  const glm::dvec3 offset = GetParam().distance * glm::normalize(glm::dvec3(1.0, -0.5, 0.75));
  facet::testing::translateScene(scene, offset);
  expectParity(device_, scene);
}

INSTANTIATE_TEST_SUITE_P(Translated, FarFromTheOrigin,
                         ::testing::Values(FarCase{"suzanne", scene::IntersectionMethod::Exact, 1e3},
                                           FarCase{"suzanne", scene::IntersectionMethod::Exact, 1e6},
                                           FarCase{"suzanne", scene::IntersectionMethod::Tessellated, 1e6},
                                           FarCase{"creased_box", scene::IntersectionMethod::Exact, 1e6},
                                           FarCase{"creased_box", scene::IntersectionMethod::Tessellated, 1e6}),
                         [](const ::testing::TestParamInfo<FarCase>& info) {
                           return info.param.cage +
                                  (info.param.method == scene::IntersectionMethod::Exact ? "_exact_" : "_tess_") +
                                  std::to_string(int(std::round(std::log10(info.param.distance))));
                         });

// The GPU's float coordinates relative to the eye: a scene just inside their
// bound renders as the CPU does; one beyond it is refused, not drawn wrong.
// The cube cage, its lights and camera scaled about the world origin.
scene::Scene scaledCube(double scale, scene::IntersectionMethod method) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  for (scene::Object& object : scene.objects)
    for (glm::dvec3& p : object.cage.positions) p *= scale;
  for (scene::Light& light : scene.lights) light.position *= scale;
  scene.camera.eye *= scale;
  scene.camera.target *= scale;
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.method = method;
  return scene;
}

class FloatRange : public gpu::testing::GpuTest {};

TEST_F(FloatRange, AtTheBoundTheGpuMatchesTheCpuReference) {
  for (auto method : {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated}) {
    const scene::Scene scene = scaledCube(1.5e8, method);  // the far corner is 9e8 from the eye
    expectParity(device_, scene);
  }
}

TEST_F(FloatRange, BeyondItTheGpuRefusesTheScene) {
  // 1.5e11: the normals overflow; 1e15: the tessellated coverage goes wrong;
  // 1e39: past float.
  for (double scale : {1.5e11, 1e15, 1e39}) {
    const scene::Scene scene = scaledCube(scale, scene::IntersectionMethod::Tessellated);
    gpu_backend::GpuRenderer renderer(device_);
    try {
      renderer.render(scene, scene::buildGeometry(scene));
      ADD_FAILURE() << "rendered a cube scaled by " << scale;
    } catch (const scene::InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("cube.obj: the GPU computes in float relative to the eye: "
                                                 "coordinates must lie within +-1e9 of it"));
    }
  }
}

// An environment whose radiance times its intensity passes 1e30 would
// overflow the GPU's float sums: refused; below the bound it renders.
TEST_F(FloatRange, TheGpuRefusesAnEnvironmentBeyondFloatsReach) {
  scene::Scene scene = scaledCube(1.0, scene::IntersectionMethod::Tessellated);
  scene.render.width = 16;
  scene.render.height = 12;
  scene.environment = scene::Environment{};
  scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1e20)));
  gpu_backend::GpuRenderer renderer(device_);
  scene.environment->intensity = 1e9;
  EXPECT_NO_THROW(renderer.render(scene, scene::buildGeometry(scene)));
  scene.environment->intensity = 1e12;
  try {
    renderer.render(scene, scene::buildGeometry(scene));
    ADD_FAILURE() << "rendered an environment of radiance 1e32";
  } catch (const scene::InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("the GPU sums the environment in float: its radiance must be at most "
                                               "1e30: its largest texel times the intensity is 1e+32"));
  }
}

// The Fresnel terms raise an index to the fourth power in float: at the
// largest index and extinction a material may hold, glass and a conductor
// in a white furnace keep every pixel finite on both backends, lit by the
// prefiltered environment or by samples of it, with and without paths.
TEST_F(FloatRange, AtTheLargestOpticalConstantsEveryPixelIsFinite) {
  materials::MaterialSpec conductor;
  conductor.name = "conductor";
  conductor.roughness = 0.3;
  conductor.fresnel = "conductor";
  conductor.eta = conductor.k = glm::dvec3(materials::kMaxOpticalConstant);
  struct Lighting {
    scene::IblMethod method;
    int bounces;
  };
  for (const materials::MaterialSpec& spec : {testing::glassSpec(materials::kMaxOpticalConstant), conductor})
    for (const Lighting lighting : {Lighting{scene::IblMethod::Prefiltered, 0}, Lighting{scene::IblMethod::Sampled, 0},
                                    Lighting{scene::IblMethod::Sampled, 4}}) {
      SCOPED_TRACE(spec.name + ", bounces " + std::to_string(lighting.bounces));
      scene::Scene scene =
          testing::underWhite(testing::buildTestMaterial(spec), testing::uvSphereCage(8, 16), lighting.bounces, 12, 35);
      scene.environment->method = lighting.method;
      scene.render.samplesPerPixel = 1;
      const testing::PathRenders r = testing::renderBoth(device_, scene);
      for (const Image* image : {&r.reference, &r.gpu.image}) {
        const auto finite = [](const glm::vec4& p) { return std::isfinite(p.r + p.g + p.b + p.a); };
        EXPECT_TRUE(std::all_of(image->beauty.begin(), image->beauty.end(), finite))
            << (image == &r.reference ? "CPU" : "GPU");
      }
    }
}

// The texcoord AOV on the checker cube (seams, creases, corners-only rule),
// subdivided and as authored: where both backends hit the same patch their
// texture coordinates agree to kTexcoordTolerance, a few times what float
// evaluation at the GPU's own hit parameters leaves; elsewhere a seam may
// make them jump.
constexpr double kTexcoordTolerance = 1e-5;

struct TexcoordCase {
  scene::IntersectionMethod method;
  scene::Subdivision subdivision;
};

void PrintTo(const TexcoordCase& c, std::ostream* out) {
  *out << (c.method == scene::IntersectionMethod::Exact ? "exact" : "tessellated")
       << (c.subdivision == scene::Subdivision::None ? ", as authored" : ", subdivided");
}

class TexcoordParity : public gpu::testing::GpuTest, public ::testing::WithParamInterface<TexcoordCase> {};

TEST_P(TexcoordParity, TheTexcoordAovMatchesTheCpuReference) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_TEST_DATA_DIR) / "uv_checker_cube.obj");
  scene.render.width = 64;
  scene.render.height = 48;
  scene.render.method = GetParam().method;
  scene.objects.at(0).subdivision = GetParam().subdivision;
  const scene::SceneGeometry geometry = scene::buildGeometry(scene);
  const Image reference = cpu::renderReference(scene, geometry);
  gpu_backend::GpuRenderer renderer(device_);
  const Image gpu = renderer.render(scene, geometry).image;
  const ParityReport parity = compareImages(reference, gpu);
  EXPECT_TRUE(parity.pass) << describe(parity);

  std::size_t covered = 0, samePatch = 0;
  double largest = 0;
  for (std::size_t p = 0; p < reference.pixelCount(); ++p) {
    if (reference.patchId[p] == Image::kNoId || gpu.patchId[p] == Image::kNoId) continue;
    ++covered;
    if (reference.patchId[p] != gpu.patchId[p]) continue;
    ++samePatch;
    largest = std::max(largest, double(glm::distance(reference.texcoord[p], gpu.texcoord[p])));
  }
  EXPECT_LE(largest, kTexcoordTolerance);
  EXPECT_GT(covered, 300u);
  EXPECT_GT(double(samePatch), 0.95 * double(covered));
  // The coordinates are there, not zero: the checker spans [0, 1] x [0, 0.75].
  const auto [low, high] = std::minmax_element(reference.texcoord.begin(), reference.texcoord.end(),
                                               [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x; });
  EXPECT_LT(low->x, 0.1f);
  EXPECT_GT(high->x, 0.6f);
}

INSTANTIATE_TEST_SUITE_P(
    UvCheckerCube, TexcoordParity,
    ::testing::Values(TexcoordCase{scene::IntersectionMethod::Exact, scene::Subdivision::CatmullClark},
                      TexcoordCase{scene::IntersectionMethod::Tessellated, scene::Subdivision::CatmullClark},
                      TexcoordCase{scene::IntersectionMethod::Exact, scene::Subdivision::None}),
    [](const ::testing::TestParamInfo<TexcoordCase>& info) {
      return std::string(info.param.method == scene::IntersectionMethod::Exact ? "exact" : "tess") +
             (info.param.subdivision == scene::Subdivision::None ? "_as_authored" : "_subdivided");
    });

class GpuRendererTest : public gpu::testing::GpuTest {};

// The largest dicing rate --tess-level takes covers what the CPU covers.
TEST_F(GpuRendererTest, TheLargestDicingRateMatchesTheCpuReference) {
  scene::Scene scene = scaledCube(1.0, scene::IntersectionMethod::Tessellated);
  scene.render.tessellationRate = 256;
  scene.objects.at(0).isolationLevel = 1;
  expectParity(device_, scene);
}

// A scene without lights, environment or emission has no slots per camera
// ray: it renders black with the CPU reference's coverage and AOVs, paths
// too (its buffers of slots once were too small to bind).
TEST_F(GpuRendererTest, ASceneWithoutLightRendersAsTheCpuReferenceDoes) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_EXAMPLES_DIR) / "superball.obj");
  scene.lights.clear();
  scene.environment.reset();
  scene.render.width = 16;
  scene.render.height = 16;
  for (auto method : {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated})
    for (int bounces : {0, 2}) {
      SCOPED_TRACE(std::string(method == scene::IntersectionMethod::Exact ? "exact" : "tessellated") + ", bounces " +
                   std::to_string(bounces));
      scene.render.method = method;
      scene.render.bounces = bounces;
      const Image gpu = expectParity(device_, scene);
      for (std::size_t p = 0; p < gpu.pixelCount(); ++p) ASSERT_EQ(glm::vec3(gpu.beauty[p]), glm::vec3(0.0f)) << p;
    }
}

TEST_F(GpuRendererTest, ReportsGpuTimePerStage) {
  scene::Scene scene = scene::loadScene(std::filesystem::path(FACET_CAGE_DIR) / "cube.obj");
  scene.render.width = 16;
  scene.render.height = 12;
  scene.render.method = scene::IntersectionMethod::Tessellated;
  gpu_backend::GpuRenderer renderer(device_);
  const gpu_backend::GpuRenderResult result = renderer.render(scene, scene::buildGeometry(scene));
  std::vector<std::string> names;
  for (const StageTime& stage : result.stageMilliseconds) {
    names.emplace_back(stageName(stage.stage));
    EXPECT_GT(stage.milliseconds, 0.0) << names.back();
  }
  // A bare cage is lit by the default studio environment, prefiltered first;
  // each render compiles the pipelines no earlier one made.
  EXPECT_EQ(names,
            (std::vector<std::string>{"environment", "top levels", "pipelines", "dice grid", "dice cells", "quadtrees",
                                      "refit", "intersect", "surface", "compact", "shadow rays", "gather", "resolve"}));
  scene.render.method = scene::IntersectionMethod::Exact;
  const auto namesOf = [&] {
    std::vector<std::string> stages;
    for (const StageTime& stage : renderer.render(scene, scene::buildGeometry(scene)).stageMilliseconds)
      stages.emplace_back(stageName(stage.stage));
    return stages;
  };
  EXPECT_EQ(namesOf(), (std::vector<std::string>{"environment", "top levels", "pipelines", "dice cells", "quadtrees",
                                                 "refit", "intersect", "compact", "fallbacks", "surface", "shadow rays",
                                                 "shadow fallbacks", "gather", "resolve"}));
  // The same scene again: every pipeline is kept, and the diced geometry too.
  EXPECT_EQ(namesOf(), (std::vector<std::string>{"environment", "top levels", "intersect", "compact", "fallbacks",
                                                 "surface", "shadow rays", "shadow fallbacks", "gather", "resolve"}));
}

}  // namespace
}  // namespace facet
