// Iridescence (rules/shading/thin_film.h, docs/shading.md, "Iridescence"):
// the film's limits (no thickness, the base's own index, a film too thick
// to interfere), its colours, the white furnace and reciprocity of a lobe
// whose F it sets.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "materials/albedo.h"
#include "rules/rules.h"

namespace facet {
namespace {

namespace m = rules::f64;

double largestGap(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

// A film of the base's own index is not there: the base's Fresnel
// (Schlick's of its F(0)) at every angle, within what the Airy sum's floor
// on R12 R23 (1e-5) leaves (2 T121 sqrt(1e-5), about 0.006 a channel); one
// of no thickness is no film, exactly.
TEST(ThinFilm, AFilmOfNoThicknessOrOfTheBasesIndexIsNotThere) {
  for (const double f0 : {0.04, 0.3, 0.9})
    for (const double c : {1.0, 0.7, 0.4}) {
      const glm::dvec3 base = m::fresnel_schlick(glm::dvec3(f0), c);
      const double baseIndex = m::ior_of_f0(glm::dvec3(f0)).x;
      const glm::dvec3 same = m::thin_film_fresnel(c, baseIndex, 350.0, glm::dvec3(f0));
      std::printf("F0 %.2f cos %.1f: base %.4f, a film of the base's index %.4f\n", f0, c, base.x, same.x);
      EXPECT_LT(largestGap(same, base), 0.02) << f0 << " " << c;
    }
  m::BrdfParams p{};
  p.f_model = m::F_CONDUCTOR;
  p.eta = glm::dvec3(0.2, 0.9, 1.1);
  p.k = glm::dvec3(3.9, 2.4, 1.9);
  p.iridescence = 1;
  p.iridescence_ior = 1.6;
  p.iridescence_thickness = 0;
  for (const double c : {1.0, 0.5, 0.1}) EXPECT_EQ(m::fresnel_F(p, c), m::base_fresnel_F(p, c));
}

// Against an independent port of the extension's reference GLSL
// (KHR_materials_iridescence, evalIridescence), at three films: blue over
// a metal-like base (its red channel below 0 before the clamp), a soap-like
// film over glass head-on and obliquely.
TEST(ThinFilm, MatchesTheExtensionsReference) {
  struct Case {
    double cosine, ior, nm, f0;
    glm::dvec3 expected;
  };
  const Case cases[] = {{1.0, 2.6, 70.0, 0.5, {0.0, 0.211, 0.422}},
                        {1.0, 1.3, 400.0, 0.04, {0.0075, 0.0384, 0.0160}},
                        {0.5, 1.3, 100.0, 0.04, {0.0414, 0.0341, 0.0251}}};
  for (const Case& c : cases) {
    const glm::dvec3 f = m::thin_film_fresnel(c.cosine, c.ior, c.nm, glm::dvec3(c.f0));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], c.expected[i], 6e-4) << c.nm << " nm, channel " << i;
  }
}

// Interference colours a film of a few hundred nanometres and leaves a
// thick one grey: past the eye's coherence its harmonics vanish and the
// film reflects the incoherent sum R12 + T121^2 R23 / (1 - R12 R23) in every
// channel alike.
TEST(ThinFilm, AThinFilmIsColouredAndAThickOneIsNot) {
  const glm::dvec3 glass(0.04);
  double mostColour = 0;
  for (double nm = 100; nm <= 700; nm += 50) {
    const glm::dvec3 f = m::thin_film_fresnel(1.0, 1.33, nm, glass);
    mostColour = std::max(mostColour, std::max({f.x, f.y, f.z}) - std::min({f.x, f.y, f.z}));
  }
  const glm::dvec3 thick = m::thin_film_fresnel(1.0, 1.33, 5000.0, glass);
  const double r12 = std::pow((1.33 - 1) / (1.33 + 1), 2), r23 = std::pow((1.5 - 1.33) / (1.5 + 1.33), 2);
  const double incoherent = r12 + (1 - r12) * (1 - r12) * r23 / (1 - r12 * r23);
  std::printf("largest spread between channels, 100-700 nm: %.4f; 5000 nm: %.5f %.5f %.5f (incoherent %.5f)\n",
              mostColour, thick.x, thick.y, thick.z, incoherent);
  EXPECT_GT(mostColour, 0.02);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(thick[c], incoherent, 2e-3);
}

// The white furnace: a lobe whose F is a film's never reflects more than it
// receives, for films over a dielectric and a metal, thin and thick, at
// every view (the quadrature of materials/albedo.h), and the factor mixes
// the base's F toward the film's.
TEST(ThinFilm, AFilmedLobeReflectsNoMoreThanItReceives) {
  m::BrdfParams p{};
  p.d_model = m::D_GGX;
  p.g_model = m::G_SMITH_GGX_CORRELATED;
  p.f_model = m::F_SCHLICK;
  p.alpha = 0.02;
  p.iridescence = 1;
  double most = 0;
  for (const double f0 : {0.04, 0.95})
    for (const double ior : {1.2, 1.5, 2.0})
      for (const double nm : {120.0, 300.0, 650.0}) {
        p.f0 = glm::dvec3(f0);
        p.iridescence_ior = ior;
        p.iridescence_thickness = nm;
        for (const double mu : {0.1, 0.5, 1.0}) {
          const glm::dvec3 e = materials::directionalAlbedo(p, mu, 128).albedo;
          most = std::max({most, e.x, e.y, e.z});
          EXPECT_LE(std::max({e.x, e.y, e.z}), 1.0 + 1e-6) << f0 << " " << ior << " " << nm << " " << mu;
        }
      }
  std::printf("largest albedo of a filmed lobe: %.4f\n", most);
  m::BrdfParams half = p;
  half.iridescence = 0.5;
  const glm::dvec3 base = m::base_fresnel_F(p, 0.6), film = m::fresnel_F(p, 0.6);
  EXPECT_LT(largestGap(m::fresnel_F(half, 0.6), 0.5 * (base + film)), 1e-15);
}

// F depends on the angle between the facet normal and v, which equals the
// one with l: the filmed lobe is reciprocal, f(l, v) = f(v, l).
TEST(ThinFilm, AFilmedLobeIsReciprocal) {
  m::BrdfParams p{};
  p.d_model = m::D_GGX;
  p.g_model = m::G_SMITH_GGX_CORRELATED;
  p.f_model = m::F_DIELECTRIC;
  p.eta = glm::dvec3(1.5);
  p.alpha = 0.2;
  p.diffuse = glm::dvec3(0.2);
  p.iridescence = 0.8;
  p.iridescence_ior = 1.4;
  p.iridescence_thickness = 380;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const glm::dvec3 n(0.0, 0.0, 1.0);
  int pairs = 0;
  while (pairs < 200) {
    const glm::dvec3 l = glm::normalize(glm::dvec3(u(random), u(random), std::abs(u(random)) + 0.05));
    const glm::dvec3 v = glm::normalize(glm::dvec3(u(random), u(random), std::abs(u(random)) + 0.05));
    const glm::dvec3 a = m::brdf_evaluate(p, n, l, v), b = m::brdf_evaluate(p, n, v, l);
    EXPECT_LT(largestGap(a, b), 1e-12 * std::max(1.0, glm::length(a)));
    ++pairs;
  }
}

}  // namespace
}  // namespace facet
