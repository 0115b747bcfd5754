// Samplers against their pdfs: chi-square goodness of fit of 1e6 samples
// per case, and the pdf against the Jacobian of the sampling map.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "materials/albedo.h"
#include "materials/models.h"
#include "rules/rules.h"
#include "tests/support/shading_frame.h"

namespace facet::materials {
namespace {

using facet::testing::kPi;
const double kSampledAlphas[] = {0.1, 0.5, 1.0};
const double kIncidenceDegrees[] = {15, 45, 80};

// An anisotropic lobe's tangent: off the axes and off v's plane (xz), so that
// neither the frame nor v's azimuth is special.
const glm::dvec3 kTangent(std::cos(0.5), std::sin(0.5), 0.0);

rules::f64::BrdfParams params(int d, double alpha, double anisotropy = 0.0) {
  rules::f64::BrdfParams p{};
  p.anisotropy = anisotropy;
  p.tangent = kTangent;
  p.d_model = d;
  p.g_model = rules::f64::G_SMITH_GGX;
  p.f_model = rules::f64::F_NONE;
  p.alpha = alpha;
  p.f0 = p.eta = p.k = p.diffuse = glm::dvec3(0);
  return p;
}

// A whole coated material, sampled across its lobes (sample_brdf_lobes):
// a diffuse base with a GGX lobe of `alpha`, under a coat of alpha 0.09.
rules::f64::BrdfParams coated(double alpha) {
  rules::f64::BrdfParams p = params(rules::f64::D_GGX, alpha);
  p.f_model = rules::f64::F_SCHLICK;
  p.f0 = glm::dvec3(0.04);
  p.diffuse = glm::dvec3(0.5, 0.3, 0.2);
  p.clearcoat = 0.8;
  p.clearcoat_alpha = 0.09;
  p.clearcoat_normal = glm::dvec3(0, 0, 1);
  return p;
}

// A sheen (rules/shading/sheen.h) on the coated material's base, its
// albedo's knots a constant 0.4: the sampler and its density agree for any.
rules::f64::BrdfParams sheened(double alpha) {
  rules::f64::BrdfParams p = coated(alpha);
  p.sheen_color = glm::dvec3(0.8, 0.5, 0.3);
  p.sheen_alpha = 0.25;
  p.sheen_albedo_near = p.sheen_albedo_far = glm::dvec4(0.4);
  return p;
}

struct Case {
  int technique;
  int d;
  double alpha;
  double incidence_degrees;
  double anisotropy = 0.0;
  bool coated = false;  // the whole coated material's sampler, `technique` unused
  bool sheen = false;   // with coated: a sheen on the base too, sampled across all four lobes
  std::string label() const {
    if (sheen)
      return "sheen material alpha=" + std::to_string(alpha) + " incidence=" + std::to_string(incidence_degrees);
    if (coated)
      return "coated material alpha=" + std::to_string(alpha) + " incidence=" + std::to_string(incidence_degrees);
    return std::string(modelName(kSamplingTechniques, technique)) + " d=" + std::string(modelName(kDistributions, d)) +
           " alpha=" + std::to_string(alpha) + " incidence=" + std::to_string(incidence_degrees) +
           " anisotropy=" + std::to_string(anisotropy);
  }
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const ModelName& d : kDistributions)
    for (double alpha : kSampledAlphas)
      for (double incidence : kIncidenceDegrees) all.push_back({rules::f64::SAMPLE_D, d.id, alpha, incidence});
  for (double alpha : kSampledAlphas)
    for (double incidence : kIncidenceDegrees)
      all.push_back({rules::f64::SAMPLE_GGX_VISIBLE, rules::f64::D_GGX, alpha, incidence});
  // Anisotropic lobes (alpha_t = 0.541, alpha_b = 0.1; alpha_t = 1, alpha_b =
  // 0.3): D sampling of GGX and Beckmann and GGX's visible normals.
  for (const auto& [alpha, anisotropy] : {std::pair{0.1, 0.7}, std::pair{0.3, 1.0}})
    for (double incidence : kIncidenceDegrees) {
      all.push_back({rules::f64::SAMPLE_D, rules::f64::D_GGX, alpha, incidence, anisotropy});
      all.push_back({rules::f64::SAMPLE_D, rules::f64::D_BECKMANN, alpha, incidence, anisotropy});
      all.push_back({rules::f64::SAMPLE_GGX_VISIBLE, rules::f64::D_GGX, alpha, incidence, anisotropy});
    }
  // The cosine sampler depends on neither alpha nor v: one case.
  all.push_back({rules::f64::SAMPLE_COSINE, rules::f64::D_GGX, 1.0, 45});
  // A clear coat's lobe beside the base's two.
  for (double incidence : {45.0, 80.0})
    all.push_back({rules::f64::SAMPLE_COSINE, rules::f64::D_GGX, 0.25, incidence, 0.0, true});
  // A sheen's cosine lobe beside those three.
  all.push_back({rules::f64::SAMPLE_COSINE, rules::f64::D_GGX, 0.25, 70.0, 0.0, true, true});
  return all;
}

// Upper tail of the chi-square distribution by the Wilson-Hilferty cube-root
// normal approximation (relative error of p well below 1% for dof > 50,
// which every case here has).
double chiSquareUpperTail(double statistic, double dof) {
  double variance = 2 / (9 * dof);
  double z = (std::cbrt(statistic / dof) - (1 - variance)) / std::sqrt(variance);
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

// Bins: (theta, phi) of the microfacet normal m for the microfacet samplers
// (l is binned through m = +-normalize(l + v), a bijection on sampled
// directions; the expected count of a bin is the integral of
// pdf_l(l(m)) * 4 |v.m| over the bin, 4 |v.m| being dw_l/dw_m), (theta,
// phi) of l itself for the cosine sampler. Binning by m keeps the pdf
// smooth inside every bin, whereas in l it has an integrable 1/|l + v|
// singularity near l = -v that no fixed quadrature integrates well. A
// coated material mixes lobes, so it is binned by l (its microfacet lobes
// sample visible normals, whose density in l stays bounded), with one more
// bin for the samples below the horizon.
constexpr int kThetaBins = 64;
constexpr int kPhiBins = 64;
constexpr long kSamples = 1'000'000;

struct FitResult {
  double p_value;
  double statistic;
  int dof;
};

FitResult chiSquareFit(const Case& c, unsigned seed) {
  const glm::dvec3 n(0, 0, 1);
  double incidence = c.incidence_degrees * kPi / 180;
  const glm::dvec3 v(std::sin(incidence), 0, std::cos(incidence));
  rules::f64::BrdfParams p = c.sheen    ? sheened(c.alpha)
                             : c.coated ? coated(c.alpha)
                                        : params(c.d, c.alpha, c.anisotropy);
  bool by_normal = !c.coated && c.technique != rules::f64::SAMPLE_COSINE;
  auto bin = [&](glm::dvec3 w) {
    double theta = std::acos(std::clamp(w.z, -1.0, 1.0));
    double phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    int i = std::min(kThetaBins - 1, int(theta / (kPi / 2) * kThetaBins));
    int j = std::min(kPhiBins - 1, int(phi / (2 * kPi) * kPhiBins));
    return i * kPhiBins + j;
  };

  std::vector<double> observed(kThetaBins * kPhiBins + 1, 0.0);  // the last: below the horizon
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (long s = 0; s < kSamples; ++s) {
    glm::dvec2 u(uniform(random), uniform(random));
    glm::dvec3 l =
        c.coated ? rules::f64::sample_brdf_lobes(p, n, v, u) : rules::f64::sample_direction(c.technique, p, n, v, u);
    if (c.coated && l.z <= 0) {
      observed.back() += 1;
      continue;
    }
    glm::dvec3 w = l;
    if (by_normal) {
      w = glm::normalize(l + v);
      if (w.z < 0) w = -w;
    }
    observed[bin(w)] += 1;
  }

  static const QuadratureRule rule = gaussLegendre01(6);
  std::vector<double> expected(observed.size(), 0.0);
  for (int i = 0; i < kThetaBins; ++i) {
    for (int j = 0; j < kPhiBins; ++j) {
      double theta0 = i * (kPi / 2) / kThetaBins, dtheta = (kPi / 2) / kThetaBins;
      double phi0 = j * 2 * kPi / kPhiBins, dphi = 2 * kPi / kPhiBins;
      double sum = 0;
      for (size_t a = 0; a < rule.nodes.size(); ++a) {
        for (size_t b = 0; b < rule.nodes.size(); ++b) {
          double theta = theta0 + dtheta * rule.nodes[a], phi = phi0 + dphi * rule.nodes[b];
          glm::dvec3 w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
          double density;
          if (by_normal) {
            glm::dvec3 l = glm::reflect(-v, w);
            density = rules::f64::direction_pdf(c.technique, p, n, l, v) * 4 * std::abs(glm::dot(v, w));
          } else {
            density =
                c.coated ? rules::f64::brdf_lobes_pdf(p, n, w, v) : rules::f64::direction_pdf(c.technique, p, n, w, v);
          }
          sum += rule.weights[a] * rule.weights[b] * density * std::sin(theta);
        }
      }
      expected[i * kPhiBins + j] = sum * dtheta * dphi * kSamples;
    }
  }
  if (c.coated) {
    double above = 0;
    for (double e : expected) above += e;
    expected.back() = std::max(0.0, double(kSamples) - above);
  }

  // Pool bins expecting fewer than 5 samples into one, as usual.
  double statistic = 0, pooled_observed = 0, pooled_expected = 0;
  int bins = 0;
  for (size_t k = 0; k < observed.size(); ++k) {
    if (expected[k] < 5) {
      pooled_observed += observed[k];
      pooled_expected += expected[k];
      continue;
    }
    statistic += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
    ++bins;
  }
  if (pooled_expected > 0) {
    statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
    ++bins;
  }
  int dof = bins - 1;
  return {chiSquareUpperTail(statistic, dof), statistic, dof};
}

TEST(Sampling, ChiSquareGoodnessOfFit) {
  // Each case must reach p >= 1 - 0.99^(1/cases) (Sidak), so that the whole
  // family rejects a correct sampler with probability 1%.
  std::vector<Case> all = cases();
  double threshold = 1 - std::pow(0.99, 1.0 / double(all.size()));
  double lowest = 1, lowest_anisotropic = 1;
  std::string lowest_case;
  for (size_t k = 0; k < all.size(); ++k) {
    FitResult fit = chiSquareFit(all[k], 1000 + unsigned(k));
    EXPECT_GE(fit.p_value, threshold) << all[k].label() << " chi2=" << fit.statistic << " dof=" << fit.dof;
    if (all[k].anisotropy > 0) lowest_anisotropic = std::min(lowest_anisotropic, fit.p_value);
    if (fit.p_value < lowest) {
      lowest = fit.p_value;
      lowest_case = all[k].label();
    }
  }
  std::printf("chi-square: %zu cases, Sidak threshold %.3g, lowest p %.3g (%s), lowest anisotropic p %.3g\n",
              all.size(), threshold, lowest, lowest_case.c_str(), lowest_anisotropic);
}

TEST(Sampling, PdfIsTheJacobianOfTheSamplingMap) {
  // u is uniform, so pdf(l(u)) * |dl/du1 x dl/du2| = 1 wherever the map is
  // smooth. The area element is taken by central differences (step 1e-6):
  // tolerance 1e-4 relative. This checks the solid-angle pdf, Jacobian of
  // the reflection included, independently of any binning. Points where l
  // comes near -v (|l + v| < 0.1) are skipped: there the reflection map is
  // singular and a finite difference of step 1e-6 means nothing.
  const glm::dvec3 n(0, 0, 1);
  double worst = 0;
  for (const Case& c : cases()) {
    if (c.coated) continue;  // a mixture: its map jumps between lobes
    double incidence = c.incidence_degrees * kPi / 180;
    const glm::dvec3 v(std::sin(incidence), 0, std::cos(incidence));
    rules::f64::BrdfParams p = params(c.d, c.alpha, c.anisotropy);
    for (double u1 : {0.1, 0.3, 0.5, 0.7, 0.9}) {
      for (double u2 : {0.05, 0.35, 0.6, 0.85}) {
        const double h = 1e-6;
        auto at = [&](double a, double b) {
          return rules::f64::sample_direction(c.technique, p, n, v, glm::dvec2(a, b));
        };
        if (glm::length(at(u1, u2) + v) < 0.1) continue;
        glm::dvec3 d1 = (at(u1 + h, u2) - at(u1 - h, u2)) / (2 * h);
        glm::dvec3 d2 = (at(u1, u2 + h) - at(u1, u2 - h)) / (2 * h);
        double area = glm::length(glm::cross(d1, d2));
        double product = rules::f64::direction_pdf(c.technique, p, n, at(u1, u2), v) * area;
        EXPECT_NEAR(product, 1.0, 1e-4) << c.label() << " u=" << u1 << "," << u2;
        worst = std::max(worst, std::abs(product - 1));
      }
    }
  }
  std::printf("worst |pdf * Jacobian - 1|: %.3g\n", worst);
}

TEST(Sampling, VisibleNormalsAreVisible) {
  // Every GGX visible normal faces v and lies in the upper hemisphere.
  const glm::dvec3 n(0, 0, 1);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (double alpha : {0.01, 0.5, 1.0})
    for (double incidence : {0.0, 60.0, 89.0}) {
      double t = incidence * kPi / 180;
      glm::dvec3 v(std::sin(t), 0, std::cos(t));
      for (int s = 0; s < 1000; ++s) {
        glm::dvec3 m = rules::f64::sample_ggx_visible_normal(v, alpha, {uniform(random), uniform(random)});
        EXPECT_GE(glm::dot(m, v), 0.0);
        EXPECT_GE(glm::dot(m, n), 0.0);
        EXPECT_NEAR(glm::length(m), 1.0, 1e-12);
      }
    }
}

}  // namespace
}  // namespace facet::materials
