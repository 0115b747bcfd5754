// Transmission and absorption on the CPU reference's paths (docs/rendering.md,
// "Transmission and absorption"): a glass ball in a uniform white
// environment renders the environment (the furnace), a thin and a thick slab
// of the same absorbing glass transmit exp(-sigma d), and the transparent
// presets look through (the GPU's side: tests/engine/gpu_backend/
// transmission_parity_test.cpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>

#include "engine/cpu/reference_renderer.h"
#include "materials/material.h"
#include "scenes/scene_geometry.h"
#include "tests/support/cages.h"
#include "tests/support/glass_scenes.h"
#include "tests/support/inside_sphere.h"

namespace facet {
namespace {

using testing::coveredMean;
using testing::glassSpec;
using testing::underWhite;

materials::Material build(const materials::MaterialSpec& spec) { return testing::buildTestMaterial(spec); }

glm::dvec3 renderMean(const scene::Scene& scene) {
  return coveredMean(cpu::renderReference(scene, scene::buildGeometry(scene)));
}

TEST(TransmissionRender, GlassBallInAWhiteFurnaceRendersTheEnvironment) {
  const materials::Material glass = build(glassSpec(1.5));
  const glm::dvec3 direct = renderMean(underWhite(glass, testing::uvSphereCage(32, 64), 0, 32, 35));
  const auto start = std::chrono::steady_clock::now();
  const glm::dvec3 paths = renderMean(underWhite(glass, testing::uvSphereCage(32, 64), 32, 32, 35));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("glass ball, white furnace: bounces 0 mean %.5f, bounces 32 mean %.5f %.5f %.5f (%.2f s)\n", direct.x,
              paths.x, paths.y, paths.z, seconds);
  EXPECT_LT(direct.x, 0.2);  // reflection alone
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(paths[c], 1.0, 0.01);
  // A rough ball loses what single scattering misses at each crossing, and no more.
  materials::MaterialSpec rough = glassSpec(1.5);
  rough.alpha = 0.1;
  const glm::dvec3 roughMean = renderMean(underWhite(build(rough), testing::uvSphereCage(32, 64), 32, 32, 35));
  std::printf("rough glass ball (alpha 0.1): %.5f\n", roughMean.x);
  EXPECT_LE(roughMean.x, 1.0 + 0.01);
  EXPECT_GT(roughMean.x, 0.9);
}

// Energy compensation of glass (docs/shading.md, "Energy compensation of
// glass"): a rough clear ball, and a rough clear slab seen through its
// face, compensated keep all the light, as smooth ones do, where single
// scattering loses more the rougher the glass.
TEST(TransmissionRender, CompensatedRoughGlassInAWhiteFurnaceRendersTheEnvironment) {
  for (const bool ball : {true, false})
    for (const double alpha : {0.1, 0.36}) {
      materials::MaterialSpec rough = glassSpec(1.5);
      rough.alpha = alpha;
      const materials::Material single = build(rough);
      rough.energyCompensation = true;
      const materials::Material compensated = build(rough);
      const auto furnace = [&](const materials::Material& glass) {
        return ball ? renderMean(underWhite(glass, testing::uvSphereCage(16, 32), 32, 24, 35))
                    : renderMean(underWhite(glass, testing::slab(0.5), 32, 24, 20));
      };
      const glm::dvec3 lost = furnace(single), kept = furnace(compensated);
      std::printf("rough glass %s (alpha %.2f) in the furnace: single scattering %.5f, compensated %.5f %.5f %.5f\n",
                  ball ? "ball" : "slab", alpha, lost.x, kept.x, kept.y, kept.z);
      EXPECT_LT(lost.x, kept.x - 0.01);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(kept[c], 1.0, 0.01);
    }
}

// The environment's shadow rays of a vertex inside a sealed glass solid
// would all be blocked, so none is cast; an open glass surface's inside sees
// the environment through its opening, and its vertices cast theirs.
TEST(TransmissionRender, NoEnvironmentShadowRayLeavesTheInsideOfASealedSolid) {
  const materials::Material glass = build(glassSpec(1.5));
  scene::ControlCage open = testing::uvSphereCage(16, 32);
  open.faceVertexCounts.pop_back();  // the last triangle at the south pole
  open.faceVertexIndices.resize(open.faceVertexIndices.size() - 3);
  for (const bool sealed : {true, false}) {
    const scene::Scene s = underWhite(glass, sealed ? testing::uvSphereCage(16, 32) : open, 1, 16, 35);
    const scene::SceneGeometry geometry = scene::buildGeometry(s);
    EXPECT_EQ(scene::sealsInside(s.objects.front(), geometry.objects.front()), sealed);
    cpu::ReferenceStatistics statistics;
    cpu::renderReference(s, geometry, &statistics);
    const cpu::BounceRays& inside = statistics.raysPerBounce.at(1);  // the refracted camera rays
    EXPECT_GT(inside.hits, 0u);
    if (sealed)
      EXPECT_EQ(inside.shadowRays, 0u);
    else
      EXPECT_GT(inside.shadowRays, inside.hits);
  }
}

TEST(TransmissionRender, ThinAndThickSlabsOfOneGlassTransmitBeerLambert) {
  const double depth = 0.25;
  for (double ior : {1.0, 1.5}) {
    materials::MaterialSpec spec = glassSpec(ior);
    spec.attenuationColor = glm::dvec3(0.5, 0.25, 1.0);
    spec.attenuationDistance = depth;  // exp(-sigma d) = the colour
    const glm::dvec3 thick = renderMean(underWhite(build(spec), testing::slab(depth), 12, 16, 4));
    spec.thinWalled = true;
    spec.thickness = depth;
    const glm::dvec3 thin = renderMean(underWhite(
        build(spec), scene::testing::singleFace({{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}}), 12, 16, 4));
    const double f = rules::f64::fresnel_dielectric(ior, 1.0);
    for (int c = 0; c < 3; ++c) {
      const double tau = (*spec.attenuationColor)[c];
      // The thin wall is one interface of transmittance (1 - F) tau.
      const double thickExpected = testing::slabUnderWhite(f, tau);
      const double thinExpected = f + (1 - f) * tau;
      std::printf("ior %.1f channel %d: tau %.3f, thick %.5f (expected %.5f), thin %.5f (expected %.5f)\n", ior, c, tau,
                  thick[c], thickExpected, thin[c], thinExpected);
      EXPECT_NEAR(thick[c], thickExpected, ior == 1.0 ? 2e-3 : 1e-2) << ior << " " << c;
      EXPECT_NEAR(thin[c], thinExpected, ior == 1.0 ? 2e-3 : 1e-2) << ior << " " << c;
    }
  }
}

// A path leaves a transmissive surface from the vertex itself, keeping the
// solid's far side however near (docs/rendering.md, "Leaving a transmissive
// surface"): a slab a tenth of the leaving offset thick, of an absorbing
// glass, transmits as Airy's sum says, by either intersection method.
TEST(TransmissionRender, ASlabThinnerThanTheLeavingOffsetTransmitsBeerLambert) {
  const double depth = 1e-7;
  materials::MaterialSpec spec = glassSpec(1.5);
  spec.attenuationColor = glm::dvec3(0.2, 0.5, 0.8);
  spec.attenuationDistance = depth;
  for (auto method : {scene::IntersectionMethod::Exact, scene::IntersectionMethod::Tessellated}) {
    scene::Scene s = underWhite(build(spec), testing::slab(depth), 8, 8, 4);
    s.render.method = method;
    const scene::SceneGeometry geometry = scene::buildGeometry(s);
    ASSERT_GT(rules::f64::shadow_ray_offset(geometry.bounds.diagonal(), 0.0), 10 * depth);
    const glm::dvec3 mean = coveredMean(cpu::renderReference(s, geometry));
    const double f = rules::f64::fresnel_dielectric(1.5, 1.0);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(mean[c], testing::slabUnderWhite(f, (*spec.attenuationColor)[c]), 1e-2)
          << (method == scene::IntersectionMethod::Exact ? "exact " : "tessellated ") << c;
  }
}

TEST(TransmissionRender, TransparentPresetsLookThrough) {
  for (const char* preset : {"water", "plastic-glass-low", "glass-high-ruby", "diamond"}) {
    materials::MaterialSpec spec;
    spec.preset = preset;
    spec.roughness = 0.0;
    const materials::Material material = build(spec);
    const glm::dvec3 direct = renderMean(underWhite(material, testing::uvSphereCage(16, 32), 0, 16, 35));
    const glm::dvec3 paths = renderMean(underWhite(material, testing::uvSphereCage(16, 32), 24, 16, 35));
    std::printf("%-18s bounces 0: %.4f, bounces 24: %.4f %.4f %.4f\n", preset, direct.x, paths.x, paths.y, paths.z);
    EXPECT_LT(direct.x, 0.35) << preset;
    if (std::string(preset) == "glass-high-ruby") {  // ruby: all but red absorbed
      EXPECT_GT(paths.x, 0.7);
      EXPECT_LT(paths.y, 0.3 * paths.x);
      EXPECT_LT(paths.z, 0.3 * paths.x);
    } else {
      EXPECT_GT(paths.x, 0.9) << preset;
      EXPECT_EQ(paths.x, paths.y) << preset;
    }
  }
}

// Limits per lobe kind (render.diffuse_bounces, glossy_bounces,
// transmission_bounces): a path ends at the continuation that would exceed
// its kind's limit, whatever the bounces allow.
TEST(LobeLimits, ADiffuseLimitEndsPathsAsFewerBouncesWould) {
  scene::Scene limited = testing::insideDiffuseSphere(0.5, 24, 24, 4);
  limited.render.diffuseBounces = 2;
  limited.render.glossyBounces = 0;  // the Lambertian sphere has no specular lobe to take
  const Image a = cpu::renderReference(limited, scene::buildGeometry(limited));
  const scene::Scene two = testing::insideDiffuseSphere(0.5, 2, 24, 4);
  const Image b = cpu::renderReference(two, scene::buildGeometry(two));
  for (std::size_t p = 0; p < a.pixelCount(); ++p) ASSERT_EQ(a.beauty[p], b.beauty[p]) << p;
}

TEST(LobeLimits, AGlassBallNeedsTwoTransmissions) {
  const materials::Material glass = build(glassSpec(1.5));
  double mean[3];
  for (int limit : {0, 1, 2}) {
    scene::Scene s = underWhite(glass, testing::uvSphereCage(16, 32), 16, 16, 35);
    s.render.transmissionBounces = limit;
    mean[limit] = renderMean(s).x;
  }
  std::printf("glass ball, transmission bounces 0, 1, 2: %.4f %.4f %.4f\n", mean[0], mean[1], mean[2]);
  EXPECT_EQ(mean[0], mean[1]);  // in but never out: nothing more reaches the camera
  EXPECT_LT(mean[1], 0.2);
  EXPECT_GT(mean[2], 0.9);
}

}  // namespace
}  // namespace facet
