#include "materials/albedo.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace facet::materials {

QuadratureRule gaussLegendre01(int n) {
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Newton on P_n from the Tricomi estimate of the i-th root.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1);
      double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    double w = 2 / ((1 - x * x) * derivative * derivative);
    rule.nodes[i] = 0.5 * (1 - x);
    rule.nodes[n - 1 - i] = 0.5 * (1 + x);
    rule.weights[i] = rule.weights[n - 1 - i] = 0.5 * w;
  }
  return rule;
}

namespace {

struct Integrals {
  glm::dvec3 specular{0.0};
  glm::dvec3 diffuse{0.0};
  glm::dvec3 coat{0.0};
  glm::dvec3 sheen{0.0};
};

// What a clear coat lets through to the base and back (rules/shading/clearcoat.h);
// 1 without one.
double throughCoat(const rules::f64::BrdfParams& params, const glm::dvec3& l, const glm::dvec3& v) {
  if (params.clearcoat == 0.0) return 1.0;
  const glm::dvec3 nc = params.clearcoat_normal;
  return rules::f64::coat_transmittance(params, glm::dot(nc, v)) *
         rules::f64::coat_transmittance(params, glm::dot(nc, l));
}

// The reflection of v about m = (theta_m, phi) (phi measured from v's
// azimuth) stays above the horizon policy, n.l = 2 (v.m)(n.m) - n.v >
// COS_EPSILON, exactly for cos(phi) > bound. Integrating over that range
// keeps the kink of the cut out of the quadrature.
double azimuthCosineBound(double cos_v, double sin_v, glm::dvec3 m) {
  double numerator = (cos_v + rules::f64::COS_EPSILON) / (2 * m.z) - cos_v * m.z;
  double denominator = sin_v * m.x;
  if (denominator <= 1e-300) return numerator < 0 ? -HUGE_VAL : HUGE_VAL;
  return numerator / denominator;
}

// What a sheen and a coat leave the base (sheen.h, clearcoat.h); 1 without.
double underLayers(const rules::f64::BrdfParams& params, const glm::dvec3& l, const glm::dvec3& v) {
  if (!rules::f64::has_sheen(params)) return throughCoat(params, l, v);
  const double scale =
      rules::f64::sheen_layer(params, 0.0, rules::f64::sheen_albedo(params, v.z), rules::f64::sheen_albedo(params, l.z))
          .base_scale;
  return scale * throughCoat(params, l, v);
}

// `value(l)` (n.l) / pdf over the cosine map: the Lambert lobe, whose
// integrand is then constant but for the layers above it, and a sheen's.
template <class Value>
glm::dvec3 cosineIntegral(const rules::f64::BrdfParams& params, const glm::dvec3& v, const QuadratureRule& rule,
                          const Value& value) {
  const glm::dvec3 n(0, 0, 1);
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      glm::dvec2 u(rule.nodes[i], rule.nodes[j]);
      glm::dvec3 l = rules::f64::sample_direction(rules::f64::SAMPLE_COSINE, params, n, v, u);
      double pdf = rules::f64::direction_pdf(rules::f64::SAMPLE_COSINE, params, n, l, v);
      if (pdf > 0) sum += rule.weights[i] * rule.weights[j] * value(l) * (l.z / pdf);
    }
  }
  return sum;
}

glm::dvec3 diffuseIntegral(const rules::f64::BrdfParams& params, const glm::dvec3& v, const QuadratureRule& rule) {
  const glm::dvec3 n(0, 0, 1);
  return cosineIntegral(params, v, rule, [&](const glm::dvec3& l) {
    return rules::f64::brdf_terms(params, n, l, v).diffuse * underLayers(params, l, v);
  });
}

// f (n.l) / pdf over the whole unit square of `lobe`'s own sampler about n
// (for GGX's visible normals G2 / G1(v) times F, smooth but for the
// horizon's kink): the anisotropic lobe, which has no symmetry about v's
// plane, and a clear coat's lobe about its normal. f is `value(l)`.
template <class Value>
glm::dvec3 sampledLobe(const rules::f64::BrdfParams& lobe, const glm::dvec3& n, const glm::dvec3& v,
                       const QuadratureRule& rule, const Value& value) {
  const int technique = rules::f64::specular_technique(lobe);
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < rule.nodes.size(); ++i)
    for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
      glm::dvec3 l = rules::f64::sample_direction(technique, lobe, n, v, {rule.nodes[i], rule.nodes[j]});
      double pdf = rules::f64::direction_pdf(technique, lobe, n, l, v);
      if (pdf > 0) sum += rule.weights[i] * rule.weights[j] * value(l) * (glm::dot(n, l) / pdf);
    }
  return sum;
}

Integrals integrate(const rules::f64::BrdfParams& params, double mu, int nodes) {
  const glm::dvec3 n(0, 0, 1);
  const double sin_v = std::sqrt(std::max(0.0, 1 - mu * mu));
  const glm::dvec3 v(sin_v, 0, mu);
  // The base's specular lobe alone (its share through a coat as a factor).
  rules::f64::BrdfParams specular = params;
  specular.diffuse = glm::dvec3(0);
  specular.clearcoat = 0;
  specular.sheen_color = glm::dvec3(0);
  auto specularValue = [&](const glm::dvec3& l) {
    return rules::f64::brdf_evaluate(specular, n, l, v) * underLayers(params, l, v);
  };
  const double alpha = rules::f64::effective_alpha(params.alpha);
  const QuadratureRule rule = gaussLegendre01(nodes);
  Integrals sum;
  if (mu <= rules::f64::COS_EPSILON) return sum;
  if (params.clearcoat != 0.0)
    sum.coat = sampledLobe(rules::f64::coat_lobe_params(params), params.clearcoat_normal, v, rule,
                           [&](const glm::dvec3& l) { return rules::f64::coat_evaluate(params, l, v); });
  if (rules::f64::has_sheen(params))
    sum.sheen = cosineIntegral(params, v, rule, [&](const glm::dvec3& l) {
      const double lobe = rules::f64::sheen_lobe(params.sheen_alpha, n, l, v);
      return rules::f64::sheen_layer(params, lobe, rules::f64::sheen_albedo(params, mu),
                                     rules::f64::sheen_albedo(params, l.z))
                 .sheen *
             throughCoat(params, l, v);
    });
  if (params.anisotropy != 0.0) {
    sum.specular = sampledLobe(specular, n, v, rule, specularValue);
    sum.diffuse = diffuseIntegral(params, v, rule);
    return sum;
  }

  // Each integrand is f (n.l) / pdf at l(u): the same functions the renderer
  // uses, so the quadrature checks them and copies nothing. Specular: u1 ->
  // theta_m through the D sampler; for each, the azimuth over its valid range
  // (symmetric about v's plane). That range is the whole circle, part of it
  // or empty as u1 grows; the u1 integral is split where it changes, so each
  // panel is smooth.
  auto polar = [&](double u1) { return rules::f64::sample_microfacet_normal(params.d_model, alpha, {u1, 0.0}); };
  // Where the bound crosses target, by bisection (the D samplers run theta_m
  // up or down with u1, so the side is taken from the ends); 0 if it does
  // not cross.
  auto crossing = [&](double target) {
    auto above = [&](double u1) { return azimuthCosineBound(mu, sin_v, polar(u1)) >= target; };
    bool above_at_0 = above(0);
    if (above_at_0 == above(1)) return 0.0;
    double lo = 0, hi = 1;
    for (int k = 0; k < 60; ++k) {
      double mid = 0.5 * (lo + hi);
      (above(mid) == above_at_0 ? lo : hi) = mid;
    }
    return hi;
  };
  double edges[] = {0, crossing(-1), crossing(1), 1};
  std::sort(std::begin(edges), std::end(edges));
  for (int panel = 0; panel < 3; ++panel) {
    double u_lo = edges[panel], width = edges[panel + 1] - edges[panel];
    if (width <= 0) continue;
    for (int i = 0; i < nodes; ++i) {
      glm::dvec3 m_polar = polar(u_lo + width * rule.nodes[i]);
      double phi_max = std::acos(std::clamp(azimuthCosineBound(mu, sin_v, m_polar), -1.0, 1.0));
      if (phi_max <= 0) continue;
      for (int j = 0; j < nodes; ++j) {
        double phi = phi_max * rule.nodes[j];
        glm::dvec3 m(m_polar.x * std::cos(phi), m_polar.x * std::sin(phi), m_polar.z);
        glm::dvec3 l = glm::reflect(-v, m);
        double pdf = rules::f64::direction_pdf(rules::f64::SAMPLE_D, specular, n, l, v);
        double w = width * rule.weights[i] * rule.weights[j] * phi_max / std::numbers::pi;
        if (pdf > 0) sum.specular += w * specularValue(l) * (l.z / pdf);
      }
    }
  }

  sum.diffuse = diffuseIntegral(params, v, rule);
  return sum;
}

}  // namespace

AlbedoResult directionalAlbedo(const rules::f64::BrdfParams& params, double mu, int nodes) {
  if (nodes < 2 || nodes % 2 != 0) throw std::invalid_argument("albedo quadrature needs an even number of nodes >= 2");
  Integrals fine = integrate(params, mu, nodes);
  Integrals coarse = integrate(params, mu, nodes / 2);
  AlbedoResult result;
  result.specular = fine.specular;
  result.diffuse = fine.diffuse;
  result.coat = fine.coat;
  result.sheen = fine.sheen;
  result.albedo = fine.specular + fine.diffuse + fine.coat + fine.sheen;
  glm::dvec3 difference = glm::abs(result.albedo - (coarse.specular + coarse.diffuse + coarse.coat + coarse.sheen));
  result.error_estimate = std::max({difference.x, difference.y, difference.z});
  result.nodes = nodes;
  return result;
}

}  // namespace facet::materials
