// glTF materials as their authors meant them, on both backends: an unlit
// material shows its base colour whatever lights it, and
// KHR_materials_anisotropy stretches a highlight along the direction its
// rotation gives in the texture's frame, turned the other way on a mirrored
// layout (docs/gltf.md; docs/shading.md, "Anisotropy").
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "scenes/environment_map.h"
#include "scenes/scene_file.h"
#include "tests/support/channels_gltf.h"
#include "tests/support/path_parity.h"
#include "tests/support/studio_view.h"
#include "tests/support/textured_gltf.h"

namespace facet {
namespace {

using facet::testing::Rgba8;

class GltfMaterialParity : public testing::GpuRenderTest {
 protected:
  void SetUp() override {
    GpuRenderTest::SetUp();
    dir_ = std::filesystem::temp_directory_path() / ("facet_gltf_material_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::filesystem::remove_all(dir_);
    GpuRenderTest::TearDown();
  }

  // The textured quad of `material`, seen head-on from 3 units (the node
  // mirrored in x when `mirrored`), 48 x 48 pixels.
  scene::Scene quad(const std::string& name, const nlohmann::json& material, nlohmann::json parts, bool mirrored) {
    parts["materials"] = nlohmann::json::array({material});
    parts["nodes"] = {{{"mesh", 0}, {"scale", {mirrored ? -1.0 : 1.0, 1.0, 1.0}}}};
    scene::Scene scene = scene::loadScene(facet::testing::writeTexturedQuad(dir_, name, parts));
    scene.camera = {{0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 40.0};
    scene.render.width = scene.render.height = 48;
    return scene;
  }

  // Every covered pixel of both backends' images shows one of `colours`
  // exactly, each on a quarter of them at least, and the two agree.
  void expectUnlitColours(const testing::PathRenders& r, const glm::dvec3 (&colours)[2]);
  void expectHighlightAlong(scene::Scene scene, double imageAngle);

  std::filesystem::path dir_;
};

// sRGB-encoded 8-bit value to linear (IEC 61966-2-1), as textures decode.
double linear(std::uint8_t c) {
  const double x = c / 255.0;
  return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}

TEST_F(GltfMaterialParity, UnlitShowsItsBaseColourWhateverLightsIt) {
  const Rgba8 warm{230, 200, 40, 255}, cool{20, 60, 180, 255};
  facet::testing::writePng(dir_ / "checker.png", 8, 8, facet::testing::checkerTexels(8, 2, warm, cool));
  const glm::dvec3 factor(0.9, 0.6, 0.3);
  const nlohmann::json material = {
      {"pbrMetallicRoughness",
       {{"baseColorFactor", {factor.r, factor.g, factor.b, 1.0}}, {"baseColorTexture", {{"index", 0}}}}},
      {"doubleSided", true},
      {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}};
  // Nearest texels, so that every pixel shows one of the two colours exactly.
  const nlohmann::json parts = {{"textures", {{{"source", 0}, {"sampler", 0}}}},
                                {"images", {{{"uri", "checker.png"}}}},
                                {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}},
                                {"extensionsUsed", {"KHR_materials_unlit"}}};
  scene::Scene scene = quad("unlit", material, parts, false);
  EXPECT_TRUE(scene.warnings.empty());
  // A key light and a white sky: neither may change what the surface
  // shows, lit directly or by paths that reach it and leave it.
  scene.lights = {scene::Light{scene::LightType::Point, glm::dvec3(3.0), {0.5, 0.5, 2.0}}};
  scene.environment.emplace();
  scene.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  scene.environment->samples = 4;
  const glm::dvec3 colours[] = {factor * glm::dvec3(linear(warm.r), linear(warm.g), linear(warm.b)),
                                factor * glm::dvec3(linear(cool.r), linear(cool.g), linear(cool.b))};
  for (int bounces : {0, 2}) {
    scene.render.bounces = bounces;
    scene.environment->method = scene::IblMethod::Sampled;
    scene.environment->occlusion = bounces > 0;
    expectUnlitColours(testing::renderBoth(device_, scene), colours);
  }
}

void GltfMaterialParity::expectUnlitColours(const testing::PathRenders& r, const glm::dvec3 (&colours)[2]) {
  for (const Image* image : {&r.reference, &r.gpu.image}) {
    std::size_t covered = 0, shown[2] = {0, 0};
    for (std::size_t p = 0; p < image->beauty.size(); ++p) {
      if (image->beauty[p].a < 1.0f) continue;
      ++covered;
      const glm::dvec3 c(image->beauty[p]);
      for (int k = 0; k < 2; ++k)
        if (glm::length(c - colours[k]) < 1e-4 * glm::length(colours[k])) ++shown[k];
    }
    EXPECT_GT(covered, 1000u);
    EXPECT_EQ(shown[0] + shown[1], covered) << (image == &r.reference ? "cpu" : "gpu");
    EXPECT_GT(shown[0], covered / 4);
    EXPECT_GT(shown[1], covered / 4);
  }
  testing::expectPathParity(r, {.median = 1e-6, .p98 = 1e-5, .parted = 0});
}

TEST_F(GltfMaterialParity, UnlitVertexColoursAreTheColoursShown) {
  const nlohmann::json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}}},
                                   {"doubleSided", true},
                                   {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}};
  scene::Scene scene = scene::loadScene(facet::testing::writeChannelQuad(
      dir_, "unlit_colours", {{"POSITION", 0}, {"COLOR_0", 3}},
      {{"materials", {material}}, {"extensionsUsed", {"KHR_lights_punctual", "KHR_materials_unlit"}}}));
  EXPECT_TRUE(scene.warnings.empty());
  scene.render.width = scene.render.height = 48;
  const testing::PathRenders r = testing::renderBoth(device_, scene);
  // Near each corner, half its colour (red, green, blue at the bottom left,
  // bottom right, top right; white at the top left), whatever the light.
  const struct {
    int x, row;
    glm::dvec3 colour;
  } corners[] = {
      {7, 40, {0.5, 0.0, 0.0}}, {40, 40, {0.0, 0.5, 0.0}}, {40, 7, {0.0, 0.0, 0.5}}, {7, 7, {0.5, 0.5, 0.5}}};
  for (const Image* image : {&r.reference, &r.gpu.image})
    for (const auto& corner : corners) {
      const glm::dvec3 c(image->beauty[std::size_t(corner.row * 48 + corner.x)]);
      EXPECT_LT(glm::length(c - corner.colour), 0.1) << (image == &r.reference ? "cpu " : "gpu ") << corner.x << ","
                                                     << corner.row << ": " << c.r << " " << c.g << " " << c.b;
    }
  testing::expectPathParity(r, {.median = 1e-5, .p98 = 1e-4, .parted = 0});
}

// The highlight's principal axis in the image (radians from +x towards +y,
// image rows growing up) and its elongation (the ratio of the axes' spreads),
// over the pixels brighter than half the peak.
struct HighlightShape {
  double angle, elongation;
};

HighlightShape highlightShape(const Image& image, int width, int height) {
  double peak = 0.0;
  for (const glm::vec4& c : image.beauty) peak = std::max(peak, double(c.g));
  double w = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
  for (int row = 0; row < height; ++row)
    for (int x = 0; x < width; ++x) {
      const double g = image.beauty[std::size_t(row * width + x)].g - 0.5 * peak;
      if (g <= 0.0) continue;
      const double y = height - 1 - row;
      w += g, mx += g * x, my += g * y, xx += g * x * x, yy += g * y * y, xy += g * x * y;
    }
  mx /= w, my /= w;
  const double cxx = xx / w - mx * mx, cyy = yy / w - my * my, cxy = xy / w - mx * my;
  const double mean = 0.5 * (cxx + cyy), spread = std::sqrt(0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
  return {0.5 * std::atan2(2.0 * cxy, cxx - cyy), std::sqrt((mean + spread) / (mean - spread))};
}

// The difference of two axes' angles, modulo a half turn.
double axisDifference(double a, double b) {
  const double d = std::remainder(a - b, std::numbers::pi);
  return std::abs(d);
}

// `scene` lit by a point light between the camera and the quad, on both
// backends: a highlight stretched along `imageAngle` (within 10 degrees,
// more than twice as long as wide), and the backends in parity.
void GltfMaterialParity::expectHighlightAlong(scene::Scene scene, double imageAngle) {
  scene.environment.reset();
  scene.lights = {scene::Light{scene::LightType::Point, glm::dvec3(4.0), {0.0, 0.0, 2.0}}};
  const testing::PathRenders r = testing::renderBoth(device_, scene);
  for (const Image* image : {&r.reference, &r.gpu.image}) {
    const HighlightShape shape = highlightShape(*image, scene.render.width, scene.render.height);
    std::printf("%s: axis %.1f degrees, elongation %.2f\n", image == &r.reference ? "cpu" : "gpu",
                shape.angle * 180.0 / std::numbers::pi, shape.elongation);
    EXPECT_LT(axisDifference(shape.angle, imageAngle), 10.0 * std::numbers::pi / 180.0);
    EXPECT_GT(shape.elongation, 2.0);
  }
  testing::expectPathParity(r, {.median = 1e-4, .p98 = 1e-3, .parted = 0});
}

// Where the quad's tangent frame comes from: its texture coordinates'
// derivatives (no NORMAL), MikkTSpace's (NORMAL, no TANGENT), or the file
// (a TANGENT along +y, up the image, with the sign given).
enum class QuadFrame { Derivatives, Generated, AuthoredUp, AuthoredUpFlipped };

struct AnisotropyCase {
  double rotation;
  bool mirrored;
  double imageAngle;  // the expected axis in the image
  const char* name;
  QuadFrame frame = QuadFrame::Derivatives;
};

// `parts` with the quad's NORMALs and, for an authored frame, its TANGENTs.
nlohmann::json withFrame(const nlohmann::json& parts, QuadFrame frame, const std::filesystem::path& dir,
                         const std::string& name) {
  if (frame == QuadFrame::Derivatives) return parts;
  if (frame == QuadFrame::Generated) return testing::withQuadNormals(parts, dir, name, std::nullopt);
  return testing::withQuadNormals(parts, dir, name,
                                  std::array<float, 4>{0, 1, 0, frame == QuadFrame::AuthoredUp ? 1.0f : -1.0f});
}

class GltfAnisotropyParity : public GltfMaterialParity, public ::testing::WithParamInterface<AnisotropyCase> {};

TEST_P(GltfAnisotropyParity, TheHighlightStretchesAlongTheTexturesDirection) {
  const nlohmann::json material = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.9, 0.9, 1.0}}, {"roughnessFactor", 0.25}}},
      {"doubleSided", true},
      {"extensions",
       {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.9}, {"anisotropyRotation", GetParam().rotation}}}}}};
  const nlohmann::json parts =
      withFrame({{"extensionsUsed", {"KHR_materials_anisotropy"}}}, GetParam().frame, dir_, GetParam().name);
  scene::Scene scene = quad(GetParam().name, material, parts, GetParam().mirrored);
  EXPECT_TRUE(scene.warnings.empty());
  expectHighlightAlong(scene, GetParam().imageAngle);
}

TEST_F(GltfMaterialParity, AnisotropyTextureTurnsTheDirection) {
  // One texel pointing along the bitangent (RG (0.5, 1) is (0, 1) in the
  // tangent frame), at full strength: a quarter turn, as the rotation gives.
  facet::testing::writePng(dir_ / "direction.png", 2, 2, std::vector<Rgba8>(4, {128, 255, 255, 255}));
  const nlohmann::json anisotropy = {{"anisotropyStrength", 0.9}, {"anisotropyTexture", {{"index", 0}}}};
  const nlohmann::json material = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.9, 0.9, 1.0}}, {"roughnessFactor", 0.25}}},
      {"doubleSided", true},
      {"extensions", {{"KHR_materials_anisotropy", anisotropy}}}};
  scene::Scene scene = quad("direction_texture", material,
                            {{"extensionsUsed", {"KHR_materials_anisotropy"}},
                             {"textures", {{{"source", 0}}}},
                             {"images", {{{"uri", "direction.png"}}}}},
                            false);
  EXPECT_TRUE(scene.warnings.empty());
  expectHighlightAlong(scene, std::numbers::pi / 2);
}

TEST_F(GltfMaterialParity, ACoatTextureCoatsOnlyItsCells) {
  // A clear coat over a black base, its strength a checker of 4 x 4 cells
  // (coated where R is 1), lit from the camera: the coat's highlight shows
  // in the coated cells alone.
  facet::testing::writePng(dir_ / "coat.png", 8, 8,
                           facet::testing::checkerTexels(8, 4, {255, 255, 255, 255}, {0, 0, 0, 255}));
  const nlohmann::json coat = {
      {"clearcoatFactor", 1.0}, {"clearcoatRoughnessFactor", 0.3}, {"clearcoatTexture", {{"index", 0}}}};
  const nlohmann::json material = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.0, 0.0, 1.0}}, {"roughnessFactor", 1.0}}},
      {"doubleSided", true},
      {"extensions", {{"KHR_materials_clearcoat", coat}}}};
  scene::Scene scene = quad("coat_texture", material,
                            {{"extensionsUsed", {"KHR_materials_clearcoat"}},
                             {"textures", {{{"source", 0}, {"sampler", 0}}}},
                             {"images", {{{"uri", "coat.png"}}}},
                             {"samplers", {{{"magFilter", 9728}, {"minFilter", 9728}}}}},
                            false);
  EXPECT_TRUE(scene.warnings.empty());
  scene.environment.reset();
  scene.lights = {scene::Light{scene::LightType::Point, glm::dvec3(4.0), {0.0, 0.0, 3.0}}};
  const testing::PathRenders r = testing::renderBoth(device_, scene);
  for (const Image* image : {&r.reference, &r.gpu.image}) {
    // The four cells about the centre: the texture's cell (1, 1) is coated
    // (even), its neighbours (2, 1) and (1, 2) are not; the image's rows
    // grow down as the texture's t does.
    const auto at = [&](int x, int row) { return double(image->beauty[std::size_t(row * 48 + x)].g); };
    const double coated = at(20, 20) + at(27, 27), bare = at(27, 20) + at(20, 27);
    std::printf("%s: coated %.4f, bare %.4f\n", image == &r.reference ? "cpu" : "gpu", coated, bare);
    EXPECT_GT(coated, 10.0 * bare + 0.01);
  }
  testing::expectPathParity(r, {.median = 1e-4, .p98 = 1e-3, .parted = 0});
}

// A UV sphere of 16 x 8 quads cut into triangles, with smooth NORMALs and
// TEXCOORD_0 (longitude, latitude), in `material`, written as `name`.
std::filesystem::path writeUvSphere(const std::filesystem::path& dir, const std::string& name,
                                    const nlohmann::json& material) {
  const int around = 16, down = 8;
  std::vector<float> positions, uvs;
  std::vector<std::uint16_t> indices;
  for (int j = 0; j <= down; ++j)
    for (int i = 0; i <= around; ++i) {
      const double theta = std::numbers::pi * j / down, phi = 2 * std::numbers::pi * i / around;
      positions.insert(positions.end(), {float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                         float(-std::sin(theta) * std::sin(phi))});
      uvs.insert(uvs.end(), {float(i) / around, float(j) / down});
    }
  for (int j = 0; j < down; ++j)
    for (int i = 0; i < around; ++i) {
      const auto a = std::uint16_t(j * (around + 1) + i), c = std::uint16_t(a + around + 1);
      if (j > 0) indices.insert(indices.end(), {a, c, std::uint16_t(a + 1)});
      if (j < down - 1) indices.insert(indices.end(), {std::uint16_t(a + 1), c, std::uint16_t(c + 1)});
    }
  const std::size_t p = positions.size() * 4, t = uvs.size() * 4, n = indices.size() * 2;
  std::ofstream out(dir / (name + ".bin"), std::ios::binary);
  out.write(reinterpret_cast<const char*>(positions.data()), std::streamsize(p));  // the normals too
  out.write(reinterpret_cast<const char*>(uvs.data()), std::streamsize(t));
  out.write(reinterpret_cast<const char*>(indices.data()), std::streamsize(n));
  const std::size_t vertices = positions.size() / 3;
  const nlohmann::json file = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_materials_anisotropy"}},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}, {"NORMAL", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}}}}}}},
      {"materials", {material}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"type", "VEC3"},
         {"count", vertices},
         {"min", {-1, -1, -1}},
         {"max", {1, 1, 1}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"type", "VEC2"}, {"count", vertices}},
        {{"bufferView", 2}, {"componentType", 5123}, {"type", "SCALAR"}, {"count", indices.size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", p}},
        {{"buffer", 0}, {"byteOffset", p}, {"byteLength", t}},
        {{"buffer", 0}, {"byteOffset", p + t}, {"byteLength", n}}}},
      {"buffers", {{{"uri", name + ".bin"}, {"byteLength", p + t + n}}}}};
  std::ofstream(dir / (name + ".gltf")) << file.dump(1);
  return dir / (name + ".gltf");
}

// The largest step of brightness between horizontally neighbouring pixels
// at least 4 pixels inside the silhouette.
double largestStepInside(const Image& image) {
  const auto covered = [&](int x, int y) {
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -4; dx <= 4; ++dx) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || v < 0 || u >= image.width || v >= image.height || image.beauty[image.index(u, v)].a < 1.0f)
          return false;
      }
    return true;
  };
  const auto brightness = [&](int x, int y) {
    const glm::vec4 c = image.beauty[image.index(x, y)];
    return (c.r + c.g + c.b) / 3.0;
  };
  double largest = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x + 1 < image.width; ++x)
      if (covered(x, y) && covered(x + 1, y))
        largest = std::max(largest, std::abs(brightness(x + 1, y) - brightness(x, y)));
  return largest;
}

// A coarse brushed-metal sphere: MikkTSpace's tangents, interpolated
// across each triangle, turn the anisotropic lobe smoothly, where the
// triangles' own dP/du turn it at every edge (meridian gores,
// docs/images/mesh_tangents.png).
TEST_F(GltfMaterialParity, MeshTangentsLeaveNoGoresOnACoarseSphere) {
  const nlohmann::json brushed = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.95, 0.93, 0.88, 1.0}}, {"roughnessFactor", 0.3}}},
      {"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 1.0}}}}}};
  scene::Scene scene = scene::loadScene(writeUvSphere(dir_, "brushed_sphere", brushed));
  EXPECT_TRUE(scene.warnings.empty());
  ASSERT_FALSE(scene.objects.front().cage.faceVertexTangents.empty());
  scene = testing::studioView(scene, {{0.0, 0.8, 3.2}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 40.0}, 128);
  const testing::PathRenders smooth = testing::renderBoth(device_, scene);
  testing::expectPathParity(smooth, {.median = 1e-4, .p98 = 1e-3, .parted = 0});
  for (scene::Object& object : scene.objects) object.cage.faceVertexTangents.clear();
  const testing::PathRenders faceted = testing::renderBoth(device_, scene);
  for (const testing::PathRenders* r : {&smooth, &faceted})
    std::printf("%s: largest step cpu %.4f, gpu %.4f\n", r == &smooth ? "MikkTSpace" : "per-triangle dP/du",
                largestStepInside(r->reference), largestStepInside(r->gpu.image));
  EXPECT_LT(largestStepInside(smooth.reference), 0.5 * largestStepInside(faceted.reference));
  EXPECT_LT(largestStepInside(smooth.gpu.image), 0.5 * largestStepInside(faceted.gpu.image));
}

// The quad's u runs along +x, its v down the image: the tangent is +x and
// the rotation turns it towards +y; mirrored, the tangent is -x and the
// rotation still turns towards +y (glTF's bitangent points up the image).
// MikkTSpace's tangents agree with the derivatives'. An authored tangent
// along +y wins over both, and its sign chooses the bitangent the rotation
// turns towards: w (n x t) is -x for w = 1, +x for w = -1.
INSTANTIATE_TEST_SUITE_P(
    Rotations, GltfAnisotropyParity,
    ::testing::Values(
        AnisotropyCase{0.0, false, 0.0, "along_u"},
        AnisotropyCase{std::numbers::pi / 2, false, std::numbers::pi / 2, "quarter_turn"},
        AnisotropyCase{std::numbers::pi / 4, false, std::numbers::pi / 4, "diagonal"},
        AnisotropyCase{std::numbers::pi / 4, true, -std::numbers::pi / 4, "diagonal_mirrored"},
        AnisotropyCase{std::numbers::pi / 4, false, std::numbers::pi / 4, "generated", QuadFrame::Generated},
        AnisotropyCase{std::numbers::pi / 4, true, -std::numbers::pi / 4, "generated_mirrored", QuadFrame::Generated},
        AnisotropyCase{0.0, false, std::numbers::pi / 2, "authored_up", QuadFrame::AuthoredUp},
        AnisotropyCase{std::numbers::pi / 4, false, -std::numbers::pi / 4, "authored_diagonal", QuadFrame::AuthoredUp},
        AnisotropyCase{std::numbers::pi / 4, true, std::numbers::pi / 4, "authored_mirrored", QuadFrame::AuthoredUp},
        AnisotropyCase{std::numbers::pi / 4, false, std::numbers::pi / 4, "authored_flipped",
                       QuadFrame::AuthoredUpFlipped}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace facet
