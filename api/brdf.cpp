#include "facet/brdf.h"

#include <glm/geometric.hpp>

#include <cmath>

#include "api/errors.h"
#include "api/material.h"
#include "rules/rules.h"
#include "scenes/input_error.h"

namespace facet::v0 {
namespace {

Vec3 publicVector(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

glm::dvec3 unit(const Vec3& v, const char* name) {
  const glm::dvec3 d(v.x, v.y, v.z);
  const double length = glm::length(d);
  if (!std::isfinite(length) || length < 1e-12)
    throw scene::InputError("brdf", 0, name, "a direction must be finite and not the zero vector");
  return d / length;
}

BrdfValue evaluate(const rules::f64::BrdfParams& params, const Vec3& l, const Vec3& v) {
  const rules::f64::BrdfTerms t = rules::f64::brdf_terms(params, glm::dvec3(0, 0, 1), unit(l, "l"), unit(v, "v"));
  return {publicVector(t.value), publicVector(t.specular), publicVector(t.diffuse), publicVector(t.F), t.D, t.G};
}

}  // namespace

std::vector<BrdfValue> evaluateBrdf(const Material& material, const std::vector<Vec3>& l, const std::vector<Vec3>& v) {
  return api::translateErrors([&] {
    if (l.size() != v.size())
      throw scene::InputError(
          "brdf", 0, "l, v",
          "need as many directions each (" + std::to_string(l.size()) + " and " + std::to_string(v.size()) + ")");
    const rules::f64::BrdfParams params = materials::toParams64(api::toEngineMaterial(material, "material"));
    std::vector<BrdfValue> values;
    values.reserve(l.size());
    for (std::size_t i = 0; i < l.size(); ++i) values.push_back(evaluate(params, l[i], v[i]));
    return values;
  });
}

BrdfValue evaluateBrdf(const Material& material, const Vec3& l, const Vec3& v) {
  return evaluateBrdf(material, std::vector<Vec3>{l}, std::vector<Vec3>{v}).front();
}

}  // namespace facet::v0
