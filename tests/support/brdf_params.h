// The rules tests' usual material: a GGX lobe with correlated Smith G and
// Schlick's F over a Lambert base, about the normal +z, nothing layered.
#pragma once

#include "rules/rules.h"

namespace facet::testing {

inline rules::f64::BrdfParams schlickBase(double alpha, const glm::dvec3& f0, const glm::dvec3& diffuse) {
  rules::f64::BrdfParams p{};
  p.d_model = rules::f64::D_GGX;
  p.g_model = rules::f64::G_SMITH_GGX_CORRELATED;
  p.f_model = rules::f64::F_SCHLICK;
  p.alpha = alpha;
  p.f0 = f0;
  p.diffuse = diffuse;
  p.clearcoat_normal = glm::dvec3(0, 0, 1);
  return p;
}

}  // namespace facet::testing
