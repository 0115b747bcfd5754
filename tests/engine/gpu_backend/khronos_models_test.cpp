// The Khronos glTF sample models a test can carry (tests/scenes/data/khronos),
// each rendered on both backends and judged by what its README asks a
// person to see on its screenshot, under parity.
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "materials/material.h"
#include "scenes/environment_map.h"
#include "scenes/scene_file.h"
#include "tests/support/path_parity.h"
#include "tests/support/studio_view.h"

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

// A model seen head-on along -z from `distance` in front of `centre`, and
// where a point of the plane z = centre.z lands.
struct HeadOn {
  glm::dvec3 centre;
  double distance, fov;
  int size;
  std::size_t parted = 20;  // pixels the backends may part on (silhouettes, shadow edges)

  // Lit by the studio, or by the scene's own lights alone.
  testing::PathRenders render(gpu::Device& device, const scene::Scene& model, bool studio = true) const {
    scene::Scene scene =
        testing::studioView(model, {centre + glm::dvec3(0, 0, distance), centre, {0, 1, 0}, fov}, size);
    if (!studio) scene.environment.reset();
    const testing::PathRenders r = testing::renderBoth(device, scene);
    testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-3, .parted = parted});
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

// BoxVertexColors: a unit cube in glTF's default material (metal, rough),
// its COLOR_0 the RGB of each vertex's position: "the vertex at (0,0,0) is
// black, the vertex at (1,0,0) is red, the vertex at (1,1,0) is yellow".
// Near each corner the camera sees, the channels its coordinates set are
// bright and the others dark (the default light is grey).
TEST_F(KhronosModels, VertexColoursAreTheirCornersColours) {
  const scene::Scene scene = khronosModel("BoxVertexColors");
  EXPECT_TRUE(scene.warnings.empty());
  const testing::PathRenders r =
      testing::renderBoth(device_, testing::studioView(scene, {{2.6, 2.2, 3.0}, {0.5, 0.5, 0.5}, {0, 1, 0}, 35.0}, 96));
  testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-3, .parted = 10});
  for (const Image* image : {&r.reference, &r.gpu.image}) {
    int corners = 0;
    for (int corner = 1; corner < 8; ++corner) {  // the black corner faces away
      const glm::dvec3 at(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      glm::dvec3 sum(0.0);
      int pixels = 0;
      for (std::size_t p = 0; p < image->beauty.size(); ++p)
        if (image->beauty[p].a == 1.0f && glm::distance(glm::dvec3(image->position[p]), at) < 0.12)
          sum += glm::dvec3(image->beauty[p]), ++pixels;
      if (pixels < 3) continue;
      ++corners;
      const glm::dvec3 c = sum / double(pixels);
      double on = 1e30, off = 0.0;
      for (int k = 0; k < 3; ++k) {
        if (at[k] == 1.0)
          on = std::min(on, c[k]);
        else
          off = std::max(off, c[k]);
      }
      std::printf("%s corner (%g, %g, %g): %.3f %.3f %.3f\n", image == &r.reference ? "cpu" : "gpu", at.x, at.y, at.z,
                  c.r, c.g, c.b);
      EXPECT_GT(on, 0.1) << at.x << at.y << at.z;
      EXPECT_GT(on, 3.0 * off) << at.x << at.y << at.z;
    }
    EXPECT_EQ(corners, 7);
  }
}

// AnisotropyRotationTest: ten bands, most of them "simple" anisotropy
// stretched along the mesh's TANGENTs, which run around each band. Three
// have TANGENTs (and texture coordinates) tilted 30 degrees clockwise and
// undo the tilt by anisotropyRotation, by anisotropyTexture, or by 10 and
// 20 degrees of the two: "when the rotation is applied correctly, the
// anisotropy here should look the same as the neighboring meshes". Lit by
// a point light at the eye, a band's highlight is a streak along the lobe's
// long axis: level on every band, and tilted where a rotation is dropped.
TEST_F(KhronosModels, AnisotropyRotationsUndoTheTangentsTilt) {
  scene::Scene scene = khronosModel("AnisotropyRotationTest");
  EXPECT_TRUE(scene.warnings.empty());
  // A point light's hard shadow edges part a few more pixels.
  const HeadOn view{{0.0, 0.0, 0.0}, 40.0, 9.0, 192, 40};
  scene.lights = {scene::Light{scene::LightType::Point, glm::dvec3(4000.0), {0.0, 0.0, view.distance}}};
  // The streak's slope in degrees: the brightest row of each of 15 columns
  // across the band's middle, fitted by a line.
  const auto slope = [&](const Image& image, glm::dvec2 band) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (double dx = -0.7; dx <= 0.7 + 1e-9; dx += 0.1) {
      const glm::ivec2 top = view.pixel(band.x + dx, band.y + 0.45), bottom = view.pixel(band.x + dx, band.y - 0.45);
      int brightest = top.y;
      for (int row = top.y; row <= bottom.y; ++row)
        if (image.beauty[std::size_t(row * view.size + top.x)].g >
            image.beauty[std::size_t(brightest * view.size + top.x)].g)
          brightest = row;
      const double x = top.x, y = -brightest;
      n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return std::atan((n * sxy - sx * sy) / (n * sxx - sx * sx)) * 180.0 / std::numbers::pi;
  };
  const glm::dvec2 bands[] = {{-1.5, -2}, {-1.5, -1}, {-1.5, 0}, {-1.5, 1}, {-1.5, 2},
                              {1.5, -2},  {1.5, -1},  {1.5, 0},  {1.5, 2}};  // (1.5, 1) is a normal map
  const testing::PathRenders r = view.render(device_, scene, false);
  for (const Image* image : {&r.reference, &r.gpu.image})
    for (const glm::dvec2& band : bands) {
      const double degrees = slope(*image, band);
      std::printf("%s band (%+.1f, %+.1f): streak %+.1f degrees\n", image == &r.reference ? "cpu" : "gpu", band.x,
                  band.y, degrees);
      EXPECT_LT(std::abs(degrees), 4.0) << band.x << ", " << band.y;
    }
  // The band that undoes the tilt by anisotropyRotation alone, its rotation dropped.
  for (materials::Material& material : scene.materials) material.anisotropyRotation = 0.0;
  const testing::PathRenders dropped = view.render(device_, scene, false);
  const double tilted = slope(dropped.reference, bands[1]);
  std::printf("without its rotation: streak %+.1f degrees\n", tilted);
  EXPECT_GT(std::abs(tilted), 10.0);
}

// ClearCoatCarPaint: a red car paint (roughness 0.4, metallic 0.3, flakes
// of a tiled noise normal map) under a clear coat of roughness 0, "to
// provide a contrast with the clear coat layer": the coat draws the studio's
// key light sharp and bright over the paint's blur; without it the brightest
// pixel is the blurred paint's.
TEST_F(KhronosModels, AClearCoatDrawsTheLightSharpOverThePaint) {
  const scene::Scene coated = khronosModel("ClearCoatCarPaint");
  EXPECT_TRUE(coated.warnings.empty());
  scene::Scene bare = coated;
  for (materials::Material& m : bare.materials) m.clearcoat = 0.0;
  const HeadOn view{{0.0, 0.5, 0.0}, 3.2, 30.0, 128};
  const auto peak = [](const Image& image) {  // over the ball, not the studio behind it
    double brightest = 0.0;
    for (const glm::vec4& c : image.beauty)
      if (c.a == 1.0f) brightest = std::max(brightest, double(c.g));
    return brightest;
  };
  const testing::PathRenders withCoat = view.render(device_, coated), without = view.render(device_, bare);
  std::printf("brightest green: coated %.4f, bare %.4f\n", peak(withCoat.reference), peak(without.reference));
  EXPECT_GT(peak(withCoat.reference), 4.0 * peak(without.reference));
  EXPECT_GT(peak(withCoat.gpu.image), 4.0 * peak(without.gpu.image));
}

// SheenCloth (its top, tests/scenes/data/README.md): a blue technical
// fabric whose sheen texture holds the sheen's colour in RGB and its
// roughness in A. The screenshot shows the cloth's folds lit along their
// edges: a sheen brightens the surface towards grazing views, so the
// cloth's rim gains more from it than its middle, where the view is
// head-on. The texture's threads are smoother than the factor (A 0.44 on
// average, the factor 1), and a smoother sheen lends less light head-on.
TEST_F(KhronosModels, TheClothsSheenBrightensItsRimMoreThanItsMiddle) {
  const scene::Scene cloth = khronosModel("SheenCloth");
  EXPECT_TRUE(cloth.warnings.empty());
  ASSERT_TRUE(cloth.materials.at(0).textures.has_value());
  ASSERT_GE(cloth.materials.at(0).textures->sheenRoughnessTexture.texture, 0);
  scene::Scene bare = cloth;
  for (materials::Material& m : bare.materials) m.sheenColor = glm::dvec3(0.0);
  scene::Scene factorOnly = cloth;
  for (materials::Material& m : factorOnly.materials) m.textures->sheenRoughnessTexture = {};
  HeadOn view{{0.0, 0.036, -0.0084}, 0.08, 30.0, 72};
  view.parted = 40;
  const testing::PathRenders sheen = view.render(device_, cloth), without = view.render(device_, bare),
                             rough = view.render(device_, factorOnly);
  // Covered pixels next to the background (the rim), and those more than
  // four pixels from it (the middle).
  const auto covered = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < view.size && y < view.size &&
           sheen.reference.beauty[std::size_t(y * view.size + x)].a == 1.0f;
  };
  const auto distanceToBackground = [&](int x, int y) {
    for (int r = 1; r <= 4; ++r)
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
          if (!covered(x + dx, y + dy)) return r;
    return 5;
  };
  const auto gain = [&](const Image& with, const Image& bareImage, bool rim) {
    double a = 0.0, b = 0.0;
    for (int y = 0; y < view.size; ++y)
      for (int x = 0; x < view.size; ++x) {
        if (!covered(x, y) || (distanceToBackground(x, y) == 1) != rim || (!rim && distanceToBackground(x, y) < 5))
          continue;
        const std::size_t i = std::size_t(y * view.size + x);
        a += glm::dot(glm::dvec3(with.beauty[i]), glm::dvec3(1.0));
        b += glm::dot(glm::dvec3(bareImage.beauty[i]), glm::dvec3(1.0));
      }
    return a / b;
  };
  for (const auto& [name, with] : {std::pair{"textured", &sheen}, std::pair{"factor alone", &rough}})
    std::printf("%s: sheen's gain on the rim %.3f, in the middle %.3f (GPU %.3f, %.3f)\n", name,
                gain(with->reference, without.reference, true), gain(with->reference, without.reference, false),
                gain(with->gpu.image, without.gpu.image, true), gain(with->gpu.image, without.gpu.image, false));
  for (const auto& [with, bareImage] :
       {std::pair{&sheen.reference, &without.reference}, std::pair{&sheen.gpu.image, &without.gpu.image}}) {
    EXPECT_GT(gain(*with, *bareImage, false), 1.0);
    EXPECT_GT(gain(*with, *bareImage, true) - 1.0, 1.5 * (gain(*with, *bareImage, false) - 1.0));
  }
  EXPECT_LT(gain(sheen.reference, without.reference, false), gain(rough.reference, without.reference, false) - 0.03);
}

// ClearcoatWicker: a wicker sphere "covered with a wrinkled plastic
// clearcoat", to show a clear coat's own normal map. On the screenshot the
// coat's reflections crinkle across the weave: what the coat adds to the
// picture changes from pixel to pixel far more than a smooth coat's, which
// follows the sphere's curve.
TEST_F(KhronosModels, AWrinkledCoatCrinklesItsReflections) {
  const scene::Scene wrinkled = khronosModel("ClearcoatWicker");
  EXPECT_TRUE(wrinkled.warnings.empty());
  ASSERT_TRUE(wrinkled.materials.at(0).textures.has_value());
  ASSERT_GE(wrinkled.materials.at(0).textures->clearcoatNormalTexture.texture, 0);
  scene::Scene smooth = wrinkled;
  smooth.materials[0].textures->clearcoatNormalTexture = {};
  scene::Scene bare = wrinkled;
  bare.materials[0].clearcoat = 0.0;
  const HeadOn view{{0.0, 0.5, 0.0}, 2.6, 30.0, 64};
  const testing::PathRenders coat = view.render(device_, wrinkled), plain = view.render(device_, smooth),
                             none = view.render(device_, bare);
  // What the coat adds, and how much of it is left after a 3 x 3 blur is
  // taken away: over the sphere's pixels whose 3 x 3 neighbourhood is all
  // on it.
  const auto roughness = [&](const Image& with, const Image& without) {
    const auto added = [&](int x, int y) {
      const std::size_t i = std::size_t(y * view.size + x);
      return glm::dot(glm::dvec3(with.beauty[i]) - glm::dvec3(without.beauty[i]), glm::dvec3(1.0));
    };
    double detail = 0.0, total = 0.0;
    for (int y = 1; y + 1 < view.size; ++y)
      for (int x = 1; x + 1 < view.size; ++x) {
        double blurred = 0.0;
        bool inside = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            inside = inside && with.beauty[std::size_t((y + dy) * view.size + x + dx)].a == 1.0f;
            blurred += added(x + dx, y + dy) / 9.0;
          }
        if (!inside) continue;
        detail += std::abs(added(x, y) - blurred);
        total += std::abs(added(x, y));
      }
    return detail / total;
  };
  std::printf("the coat's detail: wrinkled %.3f (GPU %.3f), smooth %.3f (GPU %.3f)\n",
              roughness(coat.reference, none.reference), roughness(coat.gpu.image, none.gpu.image),
              roughness(plain.reference, none.reference), roughness(plain.gpu.image, none.gpu.image));
  EXPECT_GT(roughness(coat.reference, none.reference), 1.6 * roughness(plain.reference, none.reference));
  EXPECT_GT(roughness(coat.gpu.image, none.gpu.image), 1.6 * roughness(plain.gpu.image, none.gpu.image));
}

// GlamVelvetSofa (its fabric, tests/scenes/data/README.md): one mesh whose
// material KHR_materials_variants chooses among five fabrics, velvets of a
// sheen and a tinted specular F(0) over their base. The variants' screenshot
// shows a black, a champagne, a grey, a navy and a pale pink sofa: each
// variant, chosen by name, takes its own colour, the navy's blue from its
// sheen and specular colour over an almost black base.
TEST_F(KhronosModels, EachSofaVariantTakesItsOwnFabricsColour) {
  const std::filesystem::path file =
      std::filesystem::path(FACET_TEST_DATA_DIR) / "khronos" / "GlamVelvetSofa" / "GlamVelvetSofa.gltf";
  const HeadOn view{{0.0, 0.5, -0.1}, 4.0, 35.0, 64};
  const auto meanColour = [&](const Image& image) {
    glm::dvec3 sum(0.0);
    double covered = 0.0;
    for (const glm::vec4& c : image.beauty)
      if (c.a == 1.0f) sum += glm::dvec3(c), covered += 1.0;
    return sum / covered;
  };
  std::vector<std::pair<std::string, glm::dvec3>> colours;
  for (const std::string variant : {"Black", "Champagne", "Gray", "Navy", "Pale Pink"}) {
    const scene::Scene sofa = scene::loadScene(file, {}, variant);
    EXPECT_TRUE(sofa.warnings.empty()) << variant;
    const testing::PathRenders r = view.render(device_, sofa);
    const glm::dvec3 cpu = meanColour(r.reference), gpu = meanColour(r.gpu.image);
    std::printf("%-10s CPU (%.4f, %.4f, %.4f), GPU (%.4f, %.4f, %.4f)\n", variant.c_str(), cpu.r, cpu.g, cpu.b, gpu.r,
                gpu.g, gpu.b);
    colours.emplace_back(variant, cpu);
  }
  const auto colour = [&](const std::string& variant) {
    return std::find_if(colours.begin(), colours.end(), [&](const auto& c) { return c.first == variant; })->second;
  };
  const auto luminance = [](const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  const auto neutral = [](const glm::dvec3& c) { return std::max({c.r, c.g, c.b}) < 1.1 * std::min({c.r, c.g, c.b}); };
  const glm::dvec3 black = colour("Black"), champagne = colour("Champagne"), gray = colour("Gray"),
                   navy = colour("Navy"), pink = colour("Pale Pink");
  for (const auto& [variant, c] : colours) {
    if (variant != "Black") EXPECT_GT(luminance(c), luminance(black)) << variant << " darker than the black";
    if (variant != "Pale Pink") EXPECT_LT(luminance(c), luminance(pink)) << variant << " lighter than the pale pink";
    if (variant != "Navy") EXPECT_LT(c.b / c.r, navy.b / navy.r) << variant << " bluer than the navy";
  }
  EXPECT_TRUE(neutral(black));
  EXPECT_TRUE(neutral(gray));
  EXPECT_GT(luminance(gray), 4.0 * luminance(black));
  EXPECT_GT(navy.b, 3.0 * navy.r);
  EXPECT_GT(champagne.r, champagne.g);
  EXPECT_GT(champagne.g, champagne.b);
  EXPECT_GT(champagne.r, 1.3 * champagne.b);
  EXPECT_GT(pink.r, 1.2 * pink.g);
  EXPECT_GT(pink.r, 1.2 * pink.b);
}

// TwoSidedPlane: "a plane having the two sided material parameter enabled",
// a normal-mapped wooden board in the plane y = 0. Seen and lit from below
// it shows its other side as the top shows this one: every pixel covered,
// and as bright (a renderer that culled it would show nothing, one that kept
// the top's normal would leave it in the dark).
TEST_F(KhronosModels, ATwoSidedPlaneShowsBothSides) {
  const scene::Scene plane = khronosModel("TwoSidedPlane");
  EXPECT_TRUE(plane.warnings.empty());
  const auto fromSide = [&](double side) {
    scene::Scene scene =
        testing::studioView(plane, {{0.0, 4.0 * side, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 35.0}, 96);
    scene.environment.reset();
    scene.lights = {scene::Light{scene::LightType::Point, glm::dvec3(40.0), scene.camera.eye}};
    const testing::PathRenders r = testing::renderBoth(device_, scene);
    testing::expectPathParity(r, {.median = 1e-4, .p98 = 2e-3, .parted = 20});
    return r;
  };
  const testing::PathRenders top = fromSide(1.0), bottom = fromSide(-1.0);
  for (const auto& [a, b] :
       {std::pair{&top.reference, &bottom.reference}, std::pair{&top.gpu.image, &bottom.gpu.image}}) {
    double covered[2] = {0, 0}, brightness[2] = {0, 0};
    for (int side = 0; side < 2; ++side)
      for (const glm::vec4& c : (side == 0 ? a : b)->beauty)
        if (c.a == 1.0f) covered[side] += 1, brightness[side] += (c.r + c.g + c.b) / 3.0;
    std::printf("%s: top %.0f pixels of mean %.4f, bottom %.0f of mean %.4f\n", a == &top.reference ? "cpu" : "gpu",
                covered[0], brightness[0] / covered[0], covered[1], brightness[1] / covered[1]);
    EXPECT_GT(covered[0], 0.3 * 96 * 96);
    EXPECT_EQ(covered[1], covered[0]);
    EXPECT_NEAR(brightness[1] / covered[1], brightness[0] / covered[0], 0.2 * brightness[0] / covered[0]);
  }
}

// AttenuationTest: blue glass cubes (attenuation colour c = (0.1, 0.5, 0.9)
// over distance 1) whose thickness d is set four ways, one row each: the
// cube's size with a matching thicknessFactor, a thicknessTexture over one
// mesh, a unit cube's node scale, and a unit cube's attenuation distance
// 1/d. "An implementation can pass the test offered by this model if it
// displays a uniform shade of blue in each vertical column", the shade of
// c^d (KHR_materials_volume). Lit from behind alone, by the backdrop made a
// white emitter, light seen through a cube's centre has crossed d of the
// glass, d / cos(theta_t) along the refracted view: ln(B/R) = ln 9 times
// that in every row, which a path tracer measures in the scene rather than
// reading from the thickness.
TEST_F(KhronosModels, EveryRowOfAttenuatedGlassShowsItsColumnsShade) {
  scene::Scene model = khronosModel("AttenuationTest");
  EXPECT_TRUE(model.warnings.empty());
  const auto backdrop = std::find_if(model.materials.begin(), model.materials.end(),
                                     [](const materials::Material& m) { return m.name == "FlatBackdrop"; });
  ASSERT_NE(backdrop, model.materials.end());
  backdrop->emission = glm::dvec3(1.0);
  model.render.bounces = 2;  // into a cube, out of it, and onto the backdrop
  // Columns at x = -2, 0, 2.5, 6 (d = 0.5, 1, 1.5, 2), rows at y = 3
  // (size), 0 (texture), -3 (scale), -6 (distance); the sample row at y = 6
  // is opaque, its colour the answer for a light in front.
  const HeadOn view{{1.25, 0.0, 0.0}, 30.0, 26.0, 128};
  const testing::PathRenders r = view.render(device_, model, false);
  const double columns[][2] = {{0.5, -2.0}, {1.0, 0.0}, {1.5, 2.5}, {2.0, 6.0}};
  for (const Image* image : {&r.reference, &r.gpu.image})
    for (const auto& [d, x] : columns) {
      std::printf("%s d %.1f, ln(B/R) against ln 9 d / cos(theta_t):", image == &r.reference ? "cpu" : "gpu", d);
      for (const double y : {3.0, 0.0, -3.0, -6.0}) {
        const glm::ivec2 p = view.pixel(x, y);
        const glm::vec4 c = image->beauty[std::size_t(p.y * view.size + p.x)];
        const double shade = std::log(double(c.b) / double(c.r));
        const double sinIncidence = glm::length(glm::dvec2(x, y) - glm::dvec2(view.centre)) /
                                    glm::length(glm::dvec3(x, y, 0.0) - view.centre - glm::dvec3(0, 0, view.distance));
        const double cosInside = std::sqrt(1.0 - sinIncidence * sinIncidence / (1.5 * 1.5));  // glTF's default ior
        const double expected = std::log(9.0) * d / cosInside;
        std::printf(" %.4f (%.4f)", shade, expected);
        EXPECT_NEAR(shade, expected, 1e-3 * expected) << "d " << d << ", row at y " << y;
      }
      std::printf("\n");
    }
}

// TransmissionRoughnessTest: glass tiles (thin volumes, their base colour
// tinting what they pass) before a patterned backdrop, rougher to the right
// and of a higher index up the rows. "With IOR = 1.0, light vectors do not
// change regardless of how strong the microfacet angles become", so that
// row stays sharp at every roughness, while "progressively higher values
// for IOR will result in the apparent blurriness of transmission becoming
// stronger". Seen through a tile, the backdrop's pattern correlates with
// the backdrop rendered without the tiles: through every tile at index 1,
// through none of the rough half at 2.42. A white environment lights it
// evenly, so that what varies is the pattern.
TEST_F(KhronosModels, ARoughTransmissionBlursOnlyWhereTheIndexBends) {
  scene::Scene tiles = khronosModel("TransmissionRoughnessTest");
  EXPECT_TRUE(tiles.warnings.empty());
  tiles.environment = scene::Environment{};
  tiles.environment->map = std::make_shared<const scene::EnvironmentMap>(scene::constantEnvironment(glm::dvec3(1.0)));
  tiles.environment->method = scene::IblMethod::Sampled;
  tiles.environment->samples = 4;
  tiles.render.bounces = 2;  // into a tile, out of it, and onto the backdrop
  tiles.render.samplesPerPixel = 8;
  scene::Scene backdrop = tiles;
  std::erase_if(backdrop.objects, [&](const scene::Object& object) {
    return materials::isTransmissive(backdrop.materials[std::size_t(object.material)]);
  });
  // One row of nine tiles, 0.98 wide from x = -0.29, seen head-on from 3
  // away across 160 x 20 pixels.
  const int width = 160, height = 20;
  const double distance = 3.0, pixelsPerUnit = width / 0.98;
  const auto strip = [&](const scene::Scene& model, double y) {
    scene::Scene scene = model;
    const double fov = 2.0 * std::atan(0.5 * height / pixelsPerUnit / distance) * 180.0 / std::numbers::pi;
    scene.camera = {{0.2, y, distance}, {0.2, y, 0.0}, {0, 1, 0}, fov};
    scene.render.width = width;
    scene.render.height = height;
    const testing::PathRenders r = testing::renderBoth(device_, scene);
    // The backdrop's fine lines differ by up to 3% between float and double
    // even without bounces, and paths part at the tiles: the bulk agrees.
    testing::expectPathParity(r, {.median = 1e-3, .p98 = 0.2, .parted = 800});
    return r;
  };
  // The correlation of tile k's central 13 x 13 pixels in two renders.
  const auto throughTile = [&](const Image& a, const Image& b, int k) {
    const int centre = int(std::lround(0.5 * width + (-0.29 + 0.98 / 9 * (k + 0.5) - 0.2) * pixelsPerUnit));
    std::vector<double> x, y;
    for (int row = height / 2 - 6; row <= height / 2 + 6; ++row)
      for (int column = centre - 6; column <= centre + 6; ++column) {
        const glm::vec4 p = a.beauty[std::size_t(row * width + column)],
                        q = b.beauty[std::size_t(row * width + column)];
        x.push_back(p.r + p.g + p.b), y.push_back(q.r + q.g + q.b);
      }
    return correlation(x, y);
  };
  for (const auto& [index, y] : {std::pair{1.0, -0.22}, std::pair{2.42, 0.22}}) {
    const testing::PathRenders through = strip(tiles, y), behind = strip(backdrop, y);
    std::printf("index %.2f, smooth to rough, CPU (GPU):", index);
    for (int k = 0; k < 9; ++k) {
      const double cpu = throughTile(through.reference, behind.reference, k);
      const double gpu = throughTile(through.gpu.image, behind.gpu.image, k);
      std::printf(" %.2f (%.2f)", cpu, gpu);
      EXPECT_NEAR(gpu, cpu, 0.05) << "tile " << k;
      if (index == 1.0) {
        EXPECT_GT(cpu, 0.3) << "tile " << k;
      } else if (k >= 5) {
        EXPECT_LT(cpu, 0.25) << "tile " << k;
      }
    }
    std::printf("\n");
  }
}

}  // namespace
}  // namespace facet
