#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <fstream>
#include <numbers>

#include "scenes/input_error.h"
#include "scenes/scene_file.h"
#include "scenes/studio_environment.h"
#include "tests/support/temp_dir.h"

namespace facet::scene {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;


class SceneFiles : public facet::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    fs::copy_file(fs::path(FACET_EXAMPLES_DIR) / "superball.obj", dir_ / "ball.obj");
  }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  std::string errorOf(const std::string& json) {
    try {
      loadScene(write("scene.json", json));
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

TEST_F(SceneFiles, ThePreviewSceneHasEveryPreset) {
  Scene scene = loadScene(fs::path(FACET_EXAMPLES_DIR) / "preview.json");
  EXPECT_EQ(scene.objects.size(), 10u);
  EXPECT_EQ(scene.materials.size(), 10u);
  EXPECT_EQ(scene.lights.size(), 1u);
  ASSERT_TRUE(scene.environment.has_value());
  EXPECT_EQ(scene.environment->map->width, 256);
  EXPECT_EQ(scene.render.width, 768);
  for (const Object& o : scene.objects) EXPECT_EQ(scene.materials[std::size_t(o.material)].name, o.name);
}

TEST_F(SceneFiles, APresetNameAsAnObjectsMaterialIsThatPresetAtTheDefaultRoughness) {
  const Scene scene = loadScene(write("preset.json", R"({"objects": [{"mesh": "ball.obj", "material": "gold"}]})"));
  const materials::Material& gold = scene.materials.at(std::size_t(scene.objects.at(0).material));
  EXPECT_DOUBLE_EQ(gold.alpha, defaultMaterial().alpha);
  EXPECT_GT(gold.f0.r, 0.9);  // the gold preset's F(0), not the default material's 0.04
}

TEST_F(SceneFiles, TransformsMoveTheCageAndMirrorsKeepNormalsOutward) {
  Scene plain = loadScene(write("a.json", R"({"objects": [{"mesh": "ball.obj"}]})"));
  Scene moved = loadScene(write("b.json", R"({"objects": [{"mesh": "ball.obj",
      "transform": {"translate": [1, 2, 3], "scale": [-1, 1, 1]}}]})"));
  const ControlCage& a = plain.objects[0].cage;
  const ControlCage& b = moved.objects[0].cage;
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  for (int i = 0; i < a.vertexCount(); ++i) {
    const glm::dvec3 expected(-a.positions[std::size_t(i)].x + 1, a.positions[std::size_t(i)].y + 2,
                              a.positions[std::size_t(i)].z + 3);
    EXPECT_LT(glm::distance(b.positions[std::size_t(i)], expected), 1e-12);
  }
  // The mirror reverses each face's winding (first vertex kept).
  EXPECT_EQ(b.faceVertexIndices[0], a.faceVertexIndices[0]);
  EXPECT_EQ(b.faceVertexIndices[1], a.faceVertexIndices[3]);
  EXPECT_EQ(b.faceVertexIndices[3], a.faceVertexIndices[1]);
}

TEST_F(SceneFiles, ErrorsNameTheFileTheFieldAndTheRule) {
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "colour": [1, 0, 0]}]})"),
              AllOf(HasSubstr("scene.json"), HasSubstr("objects[0].colour"), HasSubstr("unknown field")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "camera": {"fov": 200}})"),
              AllOf(HasSubstr("camera.fov"), HasSubstr("must be in [0.001, 179]")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "missing.obj"}]})"), HasSubstr("missing.obj"));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "material": "unobtainium"}]})"),
              AllOf(HasSubstr("objects[0].material"), HasSubstr("unknown preset 'unobtainium'")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"spp": 3}})"),
              AllOf(HasSubstr("render.spp"), HasSubstr("square")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"bounces": 65}})"),
              AllOf(HasSubstr("render.bounces"), HasSubstr("[0, 64]")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"glossy_bounces": -1}})"),
              AllOf(HasSubstr("render.glossy_bounces"), HasSubstr("[0, 64]")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"bounces": 2},
                          "environment": {"color": [1, 1, 1], "method": "sampled", "occlusion": false}})"),
              AllOf(HasSubstr("scene.json"), HasSubstr("render.bounces"), HasSubstr("occlusion on")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "lights": [{"type": "point", "color": [1, 1, 1]}]})"),
              AllOf(HasSubstr("lights[0]"), HasSubstr("needs a position")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}],)"),
              AllOf(HasSubstr("not valid JSON"), HasSubstr("line 1")));
  EXPECT_THAT(errorOf(R"({"objects": []})"), AllOf(HasSubstr("objects"), HasSubstr("non-empty")));
  EXPECT_THAT(errorOf("[1]"), HasSubstr("scene.json: the document: expected an object"));
  EXPECT_THAT(errorOf("{}"), HasSubstr("scene.json: the document: a scene needs objects"));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "material": {"alpha": 2}}]})"),
              AllOf(HasSubstr("objects[0].material.alpha"), HasSubstr("[0, 1]")));
  // A matrix that flattens the cage onto a plane.
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "transform": {"matrix":
                          [1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}}]})"),
              AllOf(HasSubstr("objects[0].transform.matrix"), HasSubstr("must be invertible")));
}

TEST_F(SceneFiles, RenderBouncesDefaultToNone) {
  EXPECT_EQ(loadScene(write("direct.json", R"({"objects": [{"mesh": "ball.obj"}]})")).render.bounces, 0);
  const RenderSettings limits = loadScene(write("lobes.json", R"({"objects": [{"mesh": "ball.obj"}],
      "render": {"diffuse_bounces": 4, "transmission_bounces": 12}})"))
                                    .render;
  EXPECT_EQ(limits.diffuseBounces, 4);
  EXPECT_EQ(limits.glossyBounces, -1);  // no limit of its own
  EXPECT_EQ(limits.transmissionBounces, 12);
  EXPECT_EQ(loadScene(write("paths.json", R"({"objects": [{"mesh": "ball.obj"}], "render": {"bounces": 3},
      "environment": {"color": [1, 1, 1], "method": "sampled"}})"))
                .render.bounces,
            3);
}

// Unsaid samples are facet's to choose, with the default threshold and cap;
// spp states one pass, noise_threshold and max_spp state adaptive rounds.
TEST_F(SceneFiles, UnsaidSamplingIsChosen) {
  const RenderSettings unsaid = loadScene(write("unsaid.json", R"({"objects": [{"mesh": "ball.obj"}]})")).render;
  EXPECT_EQ(unsaid.sampling, Sampling::Chosen);
  EXPECT_EQ(unsaid.noiseThreshold, kDefaultNoiseThreshold);
  EXPECT_EQ(unsaid.maxSamplesPerPixel, kDefaultMaxSamplesPerPixel);
  EXPECT_EQ(loadScene(dir_ / "ball.obj").render.sampling, Sampling::Chosen) << "a model file says nothing of it";
  const RenderSettings pass =
      loadScene(write("pass.json", R"({"objects": [{"mesh": "ball.obj"}], "render": {"spp": 9}})")).render;
  EXPECT_EQ(pass.sampling, Sampling::OnePass);
  EXPECT_EQ(pass.samplesPerPixel, 9);
  const RenderSettings rounds = loadScene(write("rounds.json", R"({"objects": [{"mesh": "ball.obj"}],
      "render": {"noise_threshold": 0.01, "max_spp": 1024}})"))
                                    .render;
  EXPECT_EQ(rounds.sampling, Sampling::Adaptive);
  EXPECT_EQ(rounds.noiseThreshold, 0.01);
  EXPECT_EQ(rounds.maxSamplesPerPixel, 1024);
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"spp": 4, "max_spp": 64}})"),
              AllOf(HasSubstr("render.spp"), HasSubstr("not both")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"noise_threshold": 0}})"),
              AllOf(HasSubstr("render.noise_threshold"), HasSubstr("(0, 1]")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj"}], "render": {"max_spp": 4}})"),
              AllOf(HasSubstr("render.max_spp"), HasSubstr("[8, 65536]")));
}

TEST_F(SceneFiles, ObjectsChooseTheirSubdivision) {
  Scene scene = loadScene(write("schemes.json", R"({"objects": [
      {"mesh": "ball.obj"},
      {"mesh": "ball.obj", "subdivision": "none"},
      {"mesh": "ball.obj", "subdivision": "catmull-clark"},
      {"mesh": "ball.obj", "subdivision": {"isolation": 4, "end_caps": "bspline"}}]})"));
  ASSERT_EQ(scene.objects.size(), 4u);
  EXPECT_EQ(scene.objects[0].subdivision, Subdivision::CatmullClark);
  EXPECT_EQ(scene.objects[1].subdivision, Subdivision::None);
  EXPECT_EQ(scene.objects[2].subdivision, Subdivision::CatmullClark);
  EXPECT_EQ(scene.objects[3].subdivision, Subdivision::CatmullClark);
  EXPECT_EQ(scene.objects[3].isolationLevel, 4);
  EXPECT_EQ(scene.objects[3].endCaps, EndCapBasis::BSpline);

  Scene overridden = scene;
  overrideSubdivision(overridden, "none", "--subdivision");
  for (const Object& object : overridden.objects) EXPECT_EQ(object.subdivision, Subdivision::None);
  try {
    overrideSubdivision(overridden, "loop", "--subdivision");
    ADD_FAILURE() << "accepted 'loop'";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--subdivision 'loop': expected one of: catmull-clark, none");
  }

  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "subdivision": "loop"}]})"),
              AllOf(HasSubstr("scene.json"), HasSubstr("objects[0].subdivision"), HasSubstr("unknown value 'loop'"),
                    HasSubstr("catmull-clark, none")));
  EXPECT_THAT(
      errorOf(R"({"objects": [{"mesh": "ball.obj", "subdivision": 2}]})"),
      AllOf(HasSubstr("objects[0].subdivision"), HasSubstr("expected one of: catmull-clark, none, or an object")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "subdivision": {"scheme": "none"}}]})"),
              AllOf(HasSubstr("objects[0].subdivision.scheme"), HasSubstr("unknown field")));
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "subdivision": {"isolation": 11}}]})"),
              AllOf(HasSubstr("objects[0].subdivision.isolation"), HasSubstr("[1, 10]")));
}

TEST_F(SceneFiles, NonFiniteNumbersAreRejected) {
  // JSON has no NaN or Inf; a number beyond double's range is the way to write one.
  EXPECT_THAT(errorOf(R"({"objects": [{"mesh": "ball.obj", "transform": {"translate": [1e999, 0, 0]}}]})"),
              AllOf(HasSubstr("scene.json"), HasSubstr("1e999")));
}

TEST_F(SceneFiles, BrokenGltfFilesNameTheFileAndTheProblem) {
  const std::string valid = [] {
    std::ifstream in(fs::path(FACET_EXAMPLES_DIR) / "gold_cube.gltf");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  auto errorOfGltf = [&](const std::string& text) {
    try {
      loadScene(write("broken.gltf", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_THAT(errorOfGltf(valid.substr(0, valid.size() / 2)),
              AllOf(HasSubstr("broken.gltf"), HasSubstr("cannot load glTF")));
  std::string badIndex = valid;
  badIndex.replace(badIndex.find("\"indices\": 1"), 12, "\"indices\": 9");
  EXPECT_THAT(errorOfGltf(badIndex), AllOf(HasSubstr("broken.gltf"), HasSubstr("indices")));
}

TEST_F(SceneFiles, UnknownExtensionsAreRejected) {
  try {
    loadScene(write("scene.txt", "{}"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("scene.txt"), HasSubstr("unknown scene format")));
  }
}

TEST_F(SceneFiles, GltfMeshesAreWeldedCagesWithTheirMaterialsCamerasAndLights) {
  Scene scene = loadScene(fs::path(FACET_EXAMPLES_DIR) / "gold_cube.gltf");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].subdivision, Subdivision::None);
  const ControlCage& cage = scene.objects[0].cage;
  EXPECT_EQ(cage.vertexCount(), 8);  // 24 glTF vertices split at the cube's edges
  EXPECT_EQ(cage.faceCount(), 12);
  const materials::Material& gold = scene.materials[std::size_t(scene.objects[0].material)];
  EXPECT_EQ(gold.name, "gold");
  EXPECT_NEAR(gold.f0.g, 0.71, 1e-6);  // metallic 1: c_spec is the base colour
  EXPECT_EQ(gold.diffuse, glm::dvec3(0.0));
  EXPECT_NEAR(gold.alpha, 0.25, 1e-12);  // alpha = roughness^2
  EXPECT_NEAR(scene.camera.eye.z, 6.0, 1e-12);
  EXPECT_NEAR(scene.camera.verticalFovDegrees, 0.6 * 180 / std::numbers::pi, 1e-9);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_NEAR(scene.lights[0].color.r, 1.0, 1e-6);  // intensity pi / pi
  EXPECT_NEAR(glm::dot(scene.lights[0].direction, glm::normalize(glm::dvec3(0, -1, -1))), 1.0, 1e-6);
}

TEST_F(SceneFiles, ABareCageIsFramedAndLit) {
  Scene scene = loadScene(dir_ / "ball.obj");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].subdivision, Subdivision::CatmullClark);
  EXPECT_TRUE(scene.lights.empty());
  ASSERT_TRUE(scene.environment.has_value());
  EXPECT_TRUE(isStudioEnvironment(*scene.environment));
  // Every control point lies inside the view frustum.
  const glm::dvec3 forward = glm::normalize(scene.camera.target - scene.camera.eye);
  const double tanHalf = std::tan(0.5 * scene.camera.verticalFovDegrees * std::numbers::pi / 180);
  for (const glm::dvec3& p : scene.objects[0].cage.positions) {
    const glm::dvec3 d = p - scene.camera.eye;
    const double depth = glm::dot(d, forward);
    ASSERT_GT(depth, 0);
    EXPECT_LT(glm::length(d - depth * forward) / depth, tanHalf);
  }
}

TEST_F(SceneFiles, AnEnvironmentMapIsReadRelativeToTheSceneFile) {
  fs::create_directories(dir_ / "maps");
  fs::copy_file(fs::path(FACET_EXAMPLES_DIR) / "../environments/courtyard_256x128.hdr", dir_ / "maps/court.hdr");
  const Scene scene = loadScene(write("env.json", R"({"objects": [{"mesh": "ball.obj"}],
      "environment": {"file": "maps/court.hdr", "intensity": 2.5, "rotation": -90, "method": "sampled",
                      "samples": 64, "occlusion": false}})"));
  ASSERT_TRUE(scene.environment.has_value());
  const Environment& environment = *scene.environment;
  ASSERT_NE(environment.map, nullptr);
  EXPECT_EQ(environment.map->source, dir_ / "maps/court.hdr");
  EXPECT_EQ(environment.map->width, 256);
  EXPECT_EQ(environment.map->height, 128);
  EXPECT_EQ(environment.intensity, 2.5);
  EXPECT_EQ(environment.rotationDegrees, -90.0);
  EXPECT_EQ(environment.method, IblMethod::Sampled);
  EXPECT_EQ(environment.samples, 64);
  EXPECT_FALSE(environment.occlusion);
}

TEST_F(SceneFiles, AConstantEnvironmentTakesTheDefaults) {
  const Scene scene =
      loadScene(write("env.json", R"({"objects": [{"mesh": "ball.obj"}], "environment": {"color": [0.1, 0.2, 0.3]}})"));
  ASSERT_TRUE(scene.environment.has_value());
  const Environment& environment = *scene.environment;
  ASSERT_NE(environment.map, nullptr);
  EXPECT_TRUE(environment.map->source.empty());
  EXPECT_EQ(environment.map->texel(5, 2), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(environment.intensity, 1.0);
  EXPECT_EQ(environment.rotationDegrees, 0.0);
  EXPECT_EQ(environment.method, IblMethod::Prefiltered);
  EXPECT_EQ(environment.samples, 16);
  EXPECT_TRUE(environment.occlusion);
}

// Neither lights nor an environment: the studio; an environment without
// lights: the key light beside it; lights given, even none: as given.
TEST_F(SceneFiles, DefaultLightingFollowsWhatTheSceneBrings) {
  const Scene plain = loadScene(write("plain.json", R"({"objects": [{"mesh": "ball.obj"}]})"));
  EXPECT_TRUE(plain.lights.empty());
  ASSERT_TRUE(plain.environment.has_value());
  EXPECT_TRUE(isStudioEnvironment(*plain.environment));
  const Scene withMap =
      loadScene(write("map.json", R"({"objects": [{"mesh": "ball.obj"}], "environment": {"color": [0.1, 0.2, 0.3]}})"));
  EXPECT_TRUE(withMap.lights.empty()) << "no light nobody asked for beside the named environment";
  EXPECT_FALSE(isStudioEnvironment(*withMap.environment));
  const Scene dark = loadScene(write("dark.json", R"({"objects": [{"mesh": "ball.obj"}], "lights": []})"));
  EXPECT_TRUE(dark.lights.empty());
  EXPECT_FALSE(dark.environment.has_value());
}

TEST(StudioEnvironment, IsANeutralGreyOfModestRange) {
  const EnvironmentMap map = studioEnvironmentMap();
  EXPECT_EQ(map.source, kStudioEnvironmentName);
  ASSERT_EQ(map.width, 2 * map.height);
  float darkest = map.texel(0, 0).r, brightest = darkest;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const glm::vec3 t = map.texel(x, y);
      EXPECT_EQ(t.r, t.g);
      EXPECT_EQ(t.g, t.b);
      darkest = std::min(darkest, t.r);
      brightest = std::max(brightest, t.r);
    }
  EXPECT_GT(darkest, 0.05f) << "no direction is black";
  EXPECT_GT(brightest, 1.0f) << "soft boxes shape the surfaces";
  EXPECT_LT(brightest / darkest, 64.0f);
  EXPECT_GT(map.texel(0, 0).r, map.texel(0, map.height - 1).r) << "the ceiling is lighter than the floor";
}

TEST_F(SceneFiles, EnvironmentErrorsNameTheField) {
  auto errorOfEnvironment = [&](const std::string& block) {
    return errorOf(R"({"objects": [{"mesh": "ball.obj"}], "environment": )" + block + "}");
  };
  // A flat (uncompressed) Radiance file of 6 x 2 black texels: not 2:1.
  write("wide.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 6\n" + std::string(12 * 4, '\0'));
  EXPECT_THAT(errorOfEnvironment(R"({"file": "wide.hdr"})"),
              AllOf(HasSubstr("scene.json"), HasSubstr("environment.file"), HasSubstr("wide.hdr"),
                    HasSubstr("must be 2:1"), HasSubstr("6 x 2")));
  EXPECT_THAT(errorOfEnvironment(R"({"file": "missing.exr"})"),
              AllOf(HasSubstr("environment.file"), HasSubstr("missing.exr"), HasSubstr("cannot open")));
  EXPECT_THAT(errorOfEnvironment(R"({"file": "ball.obj"})"),
              AllOf(HasSubstr("environment.file"), HasSubstr("unknown environment map format")));
  EXPECT_THAT(errorOfEnvironment(R"({"file": 3})"),
              AllOf(HasSubstr("environment.file"), HasSubstr("expected a string")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, -1, 1]})"),
              AllOf(HasSubstr("environment.color"), HasSubstr("must not be negative")));
  // Light is summed in float on the GPU: radiance beyond 1e30 would make Inf pixels on either backend.
  EXPECT_THAT(
      errorOfEnvironment(R"({"color": [1e300, 1, 1]})"),
      AllOf(HasSubstr("environment.color"), HasSubstr("must be at most 1e30 per channel"), HasSubstr("1e+300")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "intensity": 1e31})"),
              AllOf(HasSubstr("environment.intensity"), HasSubstr("the brightest texel times the intensity")));
  EXPECT_THAT(
      errorOf(
          R"({"objects": [{"mesh": "ball.obj"}], "lights": [{"type": "directional", "direction": [0, -1, 0], "color": [1, 1e300, 1]}]})"),
      AllOf(HasSubstr("lights[0].color"), HasSubstr("must be at most 1e30 per channel")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1]})"),
              AllOf(HasSubstr("environment.color"), HasSubstr("expected an array of 3 numbers")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "intensity": -0.5})"),
              AllOf(HasSubstr("environment.intensity"), HasSubstr("must be in [0, inf]")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "rotation": "east"})"),
              AllOf(HasSubstr("environment.rotation"), HasSubstr("expected a number")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "method": "exact"})"),
              AllOf(HasSubstr("environment.method"), HasSubstr("unknown value 'exact'"), HasSubstr("sampled")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "samples": 0})"),
              AllOf(HasSubstr("environment.samples"), HasSubstr("must be in [1, 16384]")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "samples": 2.5})"),
              AllOf(HasSubstr("environment.samples"), HasSubstr("whole number")));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "occlusion": 1})"),
              AllOf(HasSubstr("environment.occlusion"), HasSubstr("expected true or false")));
  EXPECT_THAT(errorOfEnvironment(R"({"file": "wide.hdr", "color": [1, 1, 1]})"),
              AllOf(HasSubstr("environment"), HasSubstr("exactly one of file")));
  EXPECT_THAT(errorOfEnvironment(R"({"intensity": 2})"), HasSubstr("exactly one of file"));
  EXPECT_THAT(errorOfEnvironment(R"({"color": [1, 1, 1], "colour": [1, 1, 1]})"),
              AllOf(HasSubstr("environment.colour"), HasSubstr("unknown field")));
  EXPECT_THAT(errorOfEnvironment(R"("sky.hdr")"), AllOf(HasSubstr("environment"), HasSubstr("expected an object")));
}

}  // namespace
}  // namespace facet::scene
