// The material at a hit (rules/shading/surface_at_hit.h), the one order both
// backends apply: the normals face the eye, a texture's normal map turns the
// shading normal but not the coat's, a transmissive interface is taken from
// the side v is on, the tangent lies about the final normal, and the coat
// covers the emission.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "rules/rules.h"
#include "tests/support/shading_frame.h"
#include "tests/support/brdf_params.h"

namespace facet::rules {
namespace {

using facet::testing::kN;
namespace m = f64;

m::BrdfParams plastic() {
  m::BrdfParams p = facet::testing::schlickBase(0.2, glm::dvec3(0.04), {0.5, 0.3, 0.2});
  p.eta = glm::dvec3(1.5);
  p.clearcoat_normal = glm::dvec3(0, 1, 0);  // what the material record holds: not yet the hit's
  return p;
}

m::HitMaterial untextured(const m::BrdfParams& params) {
  m::HitMaterial h{};
  h.params = params;
  h.emission = {0.1, 0.2, 0.3};
  return h;
}

// A flat patch over (s, t) with texture coordinates u = s, v = t.
m::HitPartials flatPartials() { return {{1, 0, 0}, {0, 1, 0}, {1, 0}, {0, 1}}; }

// Every slot empty (1), both frames those of the flat patch.
m::MaterialTexels emptyTexels() {
  const m::TextureFootprint frame{{0.5, 0.5}, {1, 0}, {0, 1}, {1, 0, 0}, {0, 1, 0}, 0.0, 1.0};
  m::MaterialTexels t{};
  t.base = t.metallic_roughness = t.normal = t.emission = t.coat_normal = t.sheen = t.anisotropy = glm::dvec3(1.0);
  t.occlusion = t.coat = t.coat_roughness = t.transmission = t.specular = 1.0;
  t.iridescence = t.iridescence_thickness = 1.0;
  t.specular_color = glm::dvec3(1.0);
  t.normal_frame = t.coat_normal_frame = frame;
  t.normal_map = t.coat_normal_map = m::slot_uv_map(1.0, 0.0, {1.0, 1.0});
  return t;
}

TEST(SurfaceAtHit, NormalsFaceTheEyeAndTheSideIsTheGeometricNormals) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.1, 0, 1));
  const m::FacingNormals front = m::facing_normals(n, kN, glm::dvec3(0, 0, 1));
  EXPECT_TRUE(front.outside);
  EXPECT_EQ(front.n, n);
  EXPECT_EQ(front.ng, kN);
  const m::FacingNormals back = m::facing_normals(n, kN, glm::normalize(glm::dvec3(0.3, 0, -1)));
  EXPECT_FALSE(back.outside);
  EXPECT_EQ(back.n, -n);
  EXPECT_EQ(back.ng, -kN);
}

TEST(SurfaceAtHit, AnUntexturedOpaqueMaterialIsItsOwnParametersAboutTheFacingNormal) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.2, 0.1, 1));
  const m::BrdfParams params = plastic();
  const m::SurfaceAtHit s =
      m::surface_at_hit(untextured(params), m::facing_normals(kN, kN, v), v, m::HitPartials{});
  EXPECT_EQ(s.n, kN);
  EXPECT_EQ(s.params.diffuse, params.diffuse);
  EXPECT_EQ(s.params.alpha, params.alpha);
  EXPECT_EQ(s.params.clearcoat_normal, kN);  // the hit's, not the record's
  EXPECT_EQ(s.emission, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_EQ(s.occlusion, 1.0);
}

TEST(SurfaceAtHit, ATransmissiveInterfaceIsTakenFromTheSideTheEyeIsOn) {
  m::HitMaterial h = untextured(plastic());
  h.transmissive = true;
  h.transmission = {0.8, 1.5, false, glm::dvec3(0.0), 0.0};
  for (const double vz : {1.0, -1.0}) {
    const glm::dvec3 v = glm::normalize(glm::dvec3(0.3, 0, vz));
    const m::FacingNormals facing = m::facing_normals(kN, kN, v);
    m::BrdfParams expected = h.params;
    expected.clearcoat_normal = facing.n;
    expected = m::transmissive_brdf_params(expected, h.transmission, vz > 0, glm::dvec3(1.0), 0.0);
    const m::SurfaceAtHit s = m::surface_at_hit(h, facing, v, m::HitPartials{});
    EXPECT_EQ(s.outside, vz > 0);
    EXPECT_EQ(s.params.eta, expected.eta) << "v.z " << vz;
    EXPECT_EQ(s.params.diffuse, expected.diffuse) << "v.z " << vz;
    EXPECT_EQ(s.params.f_model, expected.f_model) << "v.z " << vz;
  }
}

// glTF: the transmission texture scales the factor; the base colour (factor
// times texel) is the metal's F(0) and the tint; where the metallic texel is
// 1 the surface reflects as the opaque metal does.
TEST(SurfaceAtHit, ATexturedTransmissiveMaterialTakesItsShareTintAndMetalPerHit) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.1, 0.2, 1));
  const glm::dvec3 l = glm::normalize(glm::dvec3(-0.4, 0.1, 1));
  m::HitMaterial h = untextured(plastic());
  h.textured = true;
  h.factors = {{0.8, 0.6, 0.4}, 1.0, 0.5, false, 1.0, 1.0, false, false, 1.0, false, glm::dvec3(0.04), 1.0};
  h.texels = emptyTexels();
  h.texels.base = glm::dvec3(0.5);
  h.texels.transmission = 0.5;
  h.texels.metallic_roughness = glm::dvec3(1.0, 1.0, 0.0);
  h.transmissive = true;
  h.transmission = {0.8, 1.5, false, glm::dvec3(0.0), 0.0};
  const m::SurfaceAtHit glass = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_EQ(glass.transmission.transmission, 0.4);
  EXPECT_EQ(glass.params.f0, glm::dvec3(0.4, 0.3, 0.2));
  EXPECT_EQ(glass.params.metallic, 0.0);
  EXPECT_EQ(glass.params.f_model, m::F_DIELECTRIC);

  h.texels.metallic_roughness = glm::dvec3(1.0);
  const m::SurfaceAtHit metal = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_EQ(metal.params.metallic, 1.0);
  EXPECT_EQ(m::dielectric_transmission(metal.params, metal.transmission), 0.0);
  const m::BrdfParams opaque =
      m::metallic_roughness_params(h.params, glm::dvec3(0.4, 0.3, 0.2), 1.0, 0.5, glm::dvec3(0.04));
  const glm::dvec3 expected = m::brdf_evaluate(opaque, kN, l, v), got = m::brdf_evaluate(metal.params, kN, l, v);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-15 * expected[c]) << c;
}

TEST(SurfaceAtHit, EmptySlotsLeaveTheGltfFactorsAndANormalMapTurnsTheBaseButNotTheCoat) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.1, 0.2, 1));
  m::HitMaterial h = untextured(plastic());
  h.params.clearcoat = 1.0;
  h.params.clearcoat_alpha = 0.01;
  h.textured = true;
  h.factors = {{0.8, 0.6, 0.4}, 0.25, 0.5, false, 1.0, 1.0, false, false, 1.0, false, glm::dvec3(0.04), 1.0};
  h.texels = emptyTexels();
  m::SurfaceAtHit s = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  const m::BrdfParams expected = m::metallic_roughness_params(h.params, h.factors.base, 0.25, 0.5, glm::dvec3(0.04));
  EXPECT_EQ(s.params.diffuse, expected.diffuse);
  EXPECT_EQ(s.params.f0, expected.f0);
  EXPECT_EQ(s.params.alpha, expected.alpha);
  EXPECT_EQ(s.n, kN);

  h.factors.normal_mapped = true;
  h.texels.normal = {0.9, 0.5, 0.7};  // tilted towards +u
  s = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_GT(s.n.x, 0.5);
  EXPECT_NEAR(glm::length(s.n), 1.0, 1e-12);
  EXPECT_EQ(s.params.clearcoat_normal, kN);
}

// A bump seen from behind (a double-sided sheet, glass from within) is the
// same bump: the mapped normal turns over with the surface, tangential
// components and all, whether the frame is the mesh's or the partials'.
TEST(SurfaceAtHit, ANormalMapSeenFromInsideIsTheSameBumpTurnedOver) {
  m::HitMaterial h = untextured(plastic());
  h.textured = true;
  h.factors = {{0.8, 0.6, 0.4}, 0.0, 0.5, true, 1.0, 1.0, false, false, 1.0, false, glm::dvec3(0.04), 1.0};
  h.texels = emptyTexels();
  h.texels.normal = {0.9, 0.3, 0.7};
  const glm::dvec3 front = glm::normalize(glm::dvec3(0.1, 0.2, 1)), back = glm::normalize(glm::dvec3(0.1, 0.2, -1));
  for (const m::HitPartials& partials : {flatPartials(), m::HitPartials{{}, {}, {}, {}, {1, 0, 0, 1}}}) {
    const m::SurfaceAtHit outside = m::surface_at_hit(h, m::facing_normals(kN, kN, front), front, partials);
    const m::SurfaceAtHit inside = m::surface_at_hit(h, m::facing_normals(kN, kN, back), back, partials);
    EXPECT_GT(outside.n.x, 0.3);
    EXPECT_EQ(inside.n, -outside.n);
  }
}

TEST(SurfaceAtHit, TheTangentLiesAboutTheFinalNormalTurnedByTheRotation) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.1, 0.2, 1));
  m::HitMaterial h = untextured(plastic());
  h.params.anisotropy = 0.8;
  h.textured = true;
  h.factors = {{1, 1, 1}, 0.0, 0.5, true, 1.0, 1.0, false, false, 1.0, false, glm::dvec3(0.04), 1.0};
  h.texels = emptyTexels();
  h.texels.normal = {0.9, 0.5, 0.7};
  const double angle = std::numbers::pi / 2;
  h.anisotropy_rotation = {std::cos(angle), std::sin(angle)};
  const m::SurfaceAtHit turned = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_NEAR(glm::dot(turned.params.tangent, turned.n), 0.0, 1e-12);
  h.anisotropy_rotation = {1.0, 0.0};
  const m::SurfaceAtHit along = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_NEAR(glm::dot(along.params.tangent, along.n), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(turned.params.tangent, along.params.tangent), 0.0, 1e-12);  // a quarter turn
  EXPECT_NEAR(along.params.tangent.y, 0.0, 1e-12);  // dP/du made orthogonal to the mapped normal
  EXPECT_GT(along.params.tangent.x, 0.0);

  h.params.anisotropy = 0.0;  // isotropic: the tangent is never built
  EXPECT_EQ(m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials()).params.tangent, glm::dvec3(0.0));
}

TEST(SurfaceAtHit, TheCoatCoversTheEmissionByItsTransmittanceTowardsTheEye) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.6, 0, 1));
  m::HitMaterial h = untextured(plastic());
  const glm::dvec3 bare = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, m::HitPartials{}).emission;
  h.params.clearcoat = 0.5;
  h.params.clearcoat_alpha = 0.01;
  const m::SurfaceAtHit coated = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, m::HitPartials{});
  EXPECT_EQ(coated.emission, bare * m::coat_transmittance(coated.params, glm::dot(kN, v)));
  EXPECT_LT(coated.emission.z, bare.z);
}

// KHR_materials_iridescence's textures: R scales the film's factor; a read
// thickness texture's G places the thickness between the minimum and the
// material's (the maximum), and an unread one leaves the maximum.
TEST(SurfaceAtHit, TheFilmsTexturesScaleItsFactorAndPlaceItsThickness) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.3, 0.1, 1));
  m::HitMaterial h = untextured(plastic());
  h.params.iridescence = 0.8;
  h.params.iridescence_ior = 1.6;
  h.params.iridescence_thickness = 500.0;
  h.textured = true;
  h.factors = {{0.8, 0.6, 0.4},  0.0, 0.5,   false, 1.0, 1.0, false, false, 1.0, false,
               glm::dvec3(0.04), 1.0, false, 100.0};
  h.texels = emptyTexels();
  const m::SurfaceAtHit untouched = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_EQ(untouched.params.iridescence, 0.8);
  EXPECT_EQ(untouched.params.iridescence_thickness, 500.0);

  h.texels.iridescence = 0.5;
  h.texels.iridescence_thickness = 0.25;
  const m::SurfaceAtHit unread = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_EQ(unread.params.iridescence, 0.4);
  EXPECT_EQ(unread.params.iridescence_thickness, 500.0);
  h.factors.film_thickness_mapped = true;
  const m::SurfaceAtHit placed = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_DOUBLE_EQ(placed.params.iridescence_thickness, 200.0);
  EXPECT_NE(m::fresnel_F(placed.params, 0.8), m::fresnel_F(unread.params, 0.8));
}

// KHR_materials_sheen's roughness texture: where it is read the hit's
// alpha and the knots the backend read between the rows replace the
// material's; where it is not they stay.
TEST(SurfaceAtHit, ATexturedSheenRoughnessGivesTheHitsAlphaAndKnots) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(0.3, 0.1, 1));
  m::HitMaterial h = untextured(plastic());
  h.params.sheen_color = glm::dvec3(0.5);
  h.params.sheen_alpha = 0.25;
  h.params.sheen_albedo_near = h.params.sheen_albedo_far = glm::dvec4(0.3);
  h.textured = true;
  h.factors = {{0.8, 0.6, 0.4},  0.0, 0.5,   false, 1.0,  1.0, false, false, 1.0, false,
               glm::dvec3(0.04), 1.0, false, 100.0, false};
  h.texels = emptyTexels();
  h.texels.sheen_alpha = m::textured_sheen_alpha(0.5, 0.4);
  h.texels.sheen_albedo_near = glm::dvec4(0.7);
  h.texels.sheen_albedo_far = glm::dvec4(0.6);
  const m::SurfaceAtHit unread = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_EQ(unread.params.sheen_alpha, 0.25);
  EXPECT_EQ(unread.params.sheen_albedo_near, glm::dvec4(0.3));
  h.factors.sheen_roughness_mapped = true;
  const m::SurfaceAtHit read = m::surface_at_hit(h, m::facing_normals(kN, kN, v), v, flatPartials());
  EXPECT_DOUBLE_EQ(read.params.sheen_alpha, 0.04);
  EXPECT_EQ(read.params.sheen_albedo_near, glm::dvec4(0.7));
  EXPECT_EQ(read.params.sheen_albedo_far, glm::dvec4(0.6));
}

}  // namespace
}  // namespace facet::rules
