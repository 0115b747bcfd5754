// Directional albedo E(mu) = integral of f(l, v) (n.l) over l, for a view
// direction at cos(theta_v) = mu, by deterministic quadrature.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

#include "rules/rules.h"

namespace facet::materials {

struct AlbedoResult {
  glm::dvec3 albedo{0.0};     // specular + diffuse + coat + sheen
  glm::dvec3 specular{0.0};   // the base's, under its sheen and coat where it has them
  glm::dvec3 diffuse{0.0};    // likewise
  glm::dvec3 coat{0.0};       // a clear coat's own reflection (rules/shading/clearcoat.h)
  glm::dvec3 sheen{0.0};      // a sheen's own reflection, through any coat (rules/shading/sheen.h)
  double error_estimate = 0;  // |E(n nodes) - E(n/2 nodes)|, largest channel
  int nodes = 0;              // Gauss-Legendre nodes per dimension
};

// The specular integral is taken over u in [0,1]^2 through the D-sampling
// map u -> m -> l, where f (n.l) / pdf = F G (v.m) / ((n.v)(n.m)) stays
// smooth however peaked D is; the diffuse one and a sheen's through the
// cosine map; a clear coat's through its own lobe's sampler.
// `nodes` (even, >= 2) per dimension.
AlbedoResult directionalAlbedo(const rules::f64::BrdfParams& params, double mu, int nodes = 256);

struct QuadratureRule {
  std::vector<double> nodes;    // in [0, 1]
  std::vector<double> weights;  // sum to 1
};
// n-point Gauss-Legendre rule mapped to [0, 1].
QuadratureRule gaussLegendre01(int n);

}  // namespace facet::materials
