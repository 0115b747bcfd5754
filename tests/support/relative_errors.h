// The per-pixel error the GPU tests hold a sampled render to, where float and
// double may part now and then: percentiles rather than a maximum.
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <vector>

#include "engine/image/image.h"

namespace facet::testing {

// Per pixel, background included, max_c |gpu - cpu| / max(max_c cpu, 1e-3 x
// the brightest), sorted.
inline std::vector<double> relativeErrors(const Image& reference, const Image& candidate) {
  float brightest = 0;
  for (const glm::vec4& b : reference.beauty) brightest = std::max({brightest, b.r, b.g, b.b});
  std::vector<double> errors;
  for (std::size_t i = 0; i < reference.beauty.size(); ++i) {
    const glm::vec3 a(reference.beauty[i]), b(candidate.beauty[i]);
    const glm::vec3 d = glm::abs(a - b);
    const double scale = std::max({a.r, a.g, a.b, 1e-3f * brightest});
    errors.push_back(std::max({d.r, d.g, d.b}) / scale);
  }
  std::sort(errors.begin(), errors.end());
  return errors;
}

}  // namespace facet::testing
