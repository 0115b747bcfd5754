// The shared texture math (rules/texture/texture_sampling.h and
// textured_material.h): wrap modes, sRGB decoding, KHR_texture_transform,
// the ray cone's level of detail, the metallic-roughness mapping and the
// normal map's tangent frame.
#include "rules/rules.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace facet::materials {
namespace {

namespace t = rules::f64;

TEST(TextureShading, WrapModesFoldTexelsIntoTheLevel) {
  // Repeat: period 4; mirrored: 0 1 2 3 3 2 1 0, period 8; clamp: the edges.
  const int repeat[] = {2, 3, 0, 1, 2, 3, 0, 1, 2, 3};
  const int mirrored[] = {1, 0, 0, 1, 2, 3, 3, 2, 1, 0};
  const int clamped[] = {0, 0, 0, 1, 2, 3, 3, 3, 3, 3};
  for (int i = -2; i < 8; ++i) {
    EXPECT_EQ(t::wrap_texel(i, 4, t::FACET_WRAP_REPEAT), repeat[i + 2]) << i;
    EXPECT_EQ(t::wrap_texel(i, 4, t::FACET_WRAP_MIRRORED_REPEAT), mirrored[i + 2]) << i;
    EXPECT_EQ(t::wrap_texel(i, 4, t::FACET_WRAP_CLAMP_TO_EDGE), clamped[i + 2]) << i;
  }
  EXPECT_EQ(t::wrap_texel(-10, 4, t::FACET_WRAP_MIRRORED_REPEAT), 1);
}

TEST(TextureShading, SrgbDecodesByTheStandardsCurve) {
  EXPECT_DOUBLE_EQ(t::srgb_to_linear(0.0), 0.0);
  EXPECT_DOUBLE_EQ(t::srgb_to_linear(1.0), 1.0);
  EXPECT_DOUBLE_EQ(t::srgb_to_linear(0.04), 0.04 / 12.92);  // the linear toe
  EXPECT_NEAR(t::srgb_to_linear(0.5), 0.214041, 1e-6);
  EXPECT_NEAR(rules::f32::srgb_to_linear(0.5f), 0.214041f, 1e-6f);
}

TEST(TextureShading, TheTransformScalesRotatesThenOffsets) {
  // KHR_texture_transform's example: rotation by pi/2 takes (1, 0) to (0, -1).
  const double c = std::cos(std::numbers::pi / 2), s = std::sin(std::numbers::pi / 2);
  const t::vec2 turned = t::transform_uv({1.0, 0.0}, {0.0, 0.0}, c, s, {1.0, 1.0});
  EXPECT_NEAR(turned.x, 0.0, 1e-15);
  EXPECT_NEAR(turned.y, -1.0, 1e-15);
  const t::vec2 moved = t::transform_uv({0.5, 0.25}, {0.1, 0.2}, 1.0, 0.0, {2.0, 4.0});
  EXPECT_NEAR(moved.x, 1.1, 1e-15);
  EXPECT_NEAR(moved.y, 1.2, 1e-15);
}

TEST(TextureShading, TheConesLevelOfDetailMatchesItsFootprintInTexels) {
  // A unit square mapped to a 256 x 256 texture: 256 texels per unit; a cone
  // 1/64 wide covers 4 texels face on (lod 2) and twice as many at 60 degrees.
  const t::vec3 ds(1, 0, 0), dt(0, 1, 0);
  const t::vec2 du(1, 0), dv(0, 1);
  EXPECT_NEAR(t::cone_texture_lod(1.0 / 64, 1.0, ds, dt, du, dv, 256, 256), 2.0, 1e-12);
  EXPECT_NEAR(t::cone_texture_lod(1.0 / 64, 0.5, ds, dt, du, dv, 256, 256), 3.0, 1e-12);
  // Texture coordinates twice as dense, one level up; a patch twice as large, one down.
  EXPECT_NEAR(t::cone_texture_lod(1.0 / 64, 1.0, ds, dt, 2.0 * du, 2.0 * dv, 256, 256), 3.0, 1e-12);
  EXPECT_NEAR(t::cone_texture_lod(1.0 / 64, 1.0, 2.0 * ds, 2.0 * dt, du, dv, 256, 256), 1.0, 1e-12);
  EXPECT_LT(t::cone_texture_lod(1.0 / 64, 1.0, ds, dt, du, 0.0 * dv, 256, 256), -60.0);
}

TEST(TextureShading, MetallicRoughnessMapsAsDocumented) {
  t::BrdfParams p{};
  p = t::metallic_roughness_params(p, {0.8, 0.4, 0.2}, 0.25, 0.5, glm::dvec3(0.04));
  EXPECT_DOUBLE_EQ(p.alpha, 0.25);
  EXPECT_NEAR(p.diffuse.r, 0.6, 1e-15);
  EXPECT_NEAR(p.f0.g, 0.04 * 0.75 + 0.4 * 0.25, 1e-15);
}

// KHR_materials_specular: the colour is capped at 1 before the factors scale it.
TEST(TextureShading, TheSpecularTexturesScaleTheDielectricsF0) {
  const glm::dvec3 f0 = t::dielectric_specular_f0({0.5, 0.1, 0.04}, 0.8, {4.0, 2.0, 0.5}, 0.5);
  EXPECT_NEAR(f0.r, 0.4, 1e-15);  // min(2, 1) x 0.4
  EXPECT_NEAR(f0.g, 0.08, 1e-15);
  EXPECT_NEAR(f0.b, 0.008, 1e-15);
  const t::BrdfParams p = t::metallic_roughness_params(t::BrdfParams{}, {0.8, 0.4, 0.2}, 0.5, 0.5, f0);
  EXPECT_NEAR(p.f0.r, 0.5 * 0.4 + 0.5 * 0.8, 1e-15);
}

// A slot that reads the surface's coordinates as they are.
const t::UvMap kSameCoordinates = t::slot_uv_map(1.0, 0.0, {1.0, 1.0});

TEST(TextureShading, TheNormalMapsFrameFollowsTheTextureCoordinates) {
  // The test quad's mapping: u along +x, v down the image along -y.
  const t::vec3 n(0, 0, 1), ds(2, 0, 0), dt(0, 2, 0);
  const t::vec2 du(0.5, 0), dv(0, -0.5);
  const t::vec4 none(0.0);
  const auto mapped = [&](t::vec2 du_ds, t::vec2 dv_dt, t::vec3 texel, double scale) {
    return t::mapped_normal(n, t::texture_frame(n, none, ds, dt, du_ds, dv_dt, kSameCoordinates), texel, scale);
  };
  // The flat texel (0.5, 0.5, 1) keeps n; +X of the map leans towards +u, +Y towards -v.
  EXPECT_EQ(mapped(du, dv, {0.5, 0.5, 1.0}, 1.0), n);
  const t::vec3 x = mapped(du, dv, {1.0, 0.5, 0.5}, 1.0);
  EXPECT_NEAR(x.x, 1.0, 1e-12);
  const t::vec3 y = mapped(du, dv, {0.5, 1.0, 1.0}, 1.0);
  EXPECT_NEAR(y.y, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(y.z, std::sqrt(0.5), 1e-12);
  // Mirrored coordinates mirror the tangent, not the map's +Y.
  const t::vec3 mirrored = mapped(-du, dv, {0.5, 1.0, 1.0}, 1.0);
  EXPECT_NEAR(mirrored.y, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(mapped(-du, dv, {1.0, 0.5, 0.5}, 1.0).x, -1.0, 1e-12);
  // Scale 0 flattens the map; coordinates that do not vary keep n.
  EXPECT_EQ(mapped(du, dv, {1.0, 1.0, 1.0}, 0.0), n);
  EXPECT_EQ(mapped(du, 0.0 * dv, {1.0, 0.5, 0.5}, 1.0), n);
}

// A mesh's tangent (glTF TANGENT) wins over the partials: the map's +X leans
// along it and +Y along w (n x t), whatever the coordinates say.
TEST(TextureShading, AMeshTangentFramesTheNormalMap) {
  const t::vec3 n(0, 0, 1), ds(2, 0, 0), dt(0, 2, 0);
  const t::vec2 du(0.5, 0), dv(0, -0.5);
  const t::vec3 leaning(0.6, 0.8, 0.0);  // off n's plane too: made orthogonal
  const t::TangentFrame frame = t::texture_frame(n, t::vec4(leaning + 0.5 * n, 1.0), ds, dt, du, dv, kSameCoordinates);
  ASSERT_TRUE(frame.defined);
  EXPECT_NEAR(glm::length(frame.t - leaning), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(frame.b - t::vec3(-0.8, 0.6, 0.0)), 0.0, 1e-12);
  const t::vec3 x = t::mapped_normal(n, frame, {1.0, 0.5, 0.5}, 1.0);
  EXPECT_NEAR(glm::length(x - leaning), 0.0, 1e-12);
  // w = -1 turns the bitangent, and so the map's +Y, over.
  const t::TangentFrame mirrored = t::texture_frame(n, t::vec4(leaning, -1.0), ds, dt, du, dv, kSameCoordinates);
  EXPECT_NEAR(glm::length(t::mapped_normal(n, mirrored, {0.5, 1.0, 0.5}, 1.0) - t::vec3(0.8, -0.6, 0.0)), 0.0, 1e-12);
  // A tangent along n gives no direction: the partials' frame stands in.
  const t::TangentFrame along = t::texture_frame(n, t::vec4(n, 1.0), ds, dt, du, dv, kSameCoordinates);
  EXPECT_EQ(along.t, t::vec3(1, 0, 0));
}

// KHR_texture_transform turns the texture on the surface, and the frame its
// normal map turns in with it: a quarter turn of the slot's coordinates
// turns t and b a quarter, the mesh's frame and the partials' alike.
TEST(TextureShading, ASlotsTransformTurnsItsFrame) {
  const t::vec3 n(0, 0, 1), ds(2, 0, 0), dt(0, 2, 0);
  const t::vec2 du(0.5, 0), dv(0, -0.5);
  const double quarter = std::acos(-1.0) / 2;
  const t::UvMap turned = t::slot_uv_map(std::cos(quarter), std::sin(quarter), {1.0, 1.0});
  const t::TangentFrame fromPartials = t::texture_frame(n, t::vec4(0.0), ds, dt, du, dv, turned);
  const t::TangentFrame fromMesh = t::texture_frame(n, t::vec4(1, 0, 0, 1), ds, dt, du, dv, turned);
  for (const t::TangentFrame& f : {fromPartials, fromMesh}) {
    ASSERT_TRUE(f.defined);
    // u' = cos u + sin v grows along dP/dv's direction, -y, here.
    EXPECT_NEAR(glm::length(f.t - t::vec3(0, -1, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(f.b - t::vec3(1, 0, 0)), 0.0, 1e-12);
  }
}

// Between corners the mesh's tangent is interpolated bilinearly, its sign
// that of the interpolated w.
TEST(TextureShading, AMeshTangentIsInterpolatedAcrossThePatch) {
  const t::vec4 x(1, 0, 0, 1), y(0, 1, 0, 1);
  const t::vec4 half = t::mesh_tangent(x, y, y, x, 0.5, 0.25);
  EXPECT_NEAR(half.x, 0.5, 1e-15);
  EXPECT_NEAR(half.y, 0.5, 1e-15);
  EXPECT_EQ(half.w, 1.0);
  EXPECT_EQ(t::mesh_tangent(x, -y, -y, x, 0.75, 0.5).w, -1.0);
}

TEST(TextureShading, OcclusionScalesByItsStrength) {
  EXPECT_DOUBLE_EQ(t::occlusion_factor(0.25, 1.0), 0.25);
  EXPECT_DOUBLE_EQ(t::occlusion_factor(0.25, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(t::occlusion_factor(0.25, 0.5), 0.625);
}

TEST(TextureShading, TheCameraConeSpreadsByOnePixel) {
  // 90 degrees over 512 rows: 2 / 512 radians, nearly.
  EXPECT_NEAR(t::camera_cone_spread(1.0, 512.0), 2.0 / 512.0, 1e-7);
}

}  // namespace
}  // namespace facet::materials
