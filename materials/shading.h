// C++ side of the shared shading source. The headers in materials/shading/
// and the punctual lights of compute/shared/lights.h are written in the
// common subset of GLSL and C++; this file gives them GLM types and GLSL's
// built-ins and instantiates them twice:
//   facet::materials::f64  double, the CPU reference
//   facet::materials::f32  float, what the GPU computes (for tests and the
//                          float-vs-double table)
// GLSL shaders include materials/shading.glsl instead.
#pragma once

#include <glm/geometric.hpp>
#include <glm/glm.hpp>

#include <limits>

#define FACET_FN inline

#define FACET_MATERIALS_GLSL_BUILTINS \
  using glm::abs;                     \
  using glm::clamp;                   \
  using glm::cos;                     \
  using glm::cross;                   \
  using glm::dot;                     \
  using glm::exp;                     \
  using glm::inversesqrt;             \
  using glm::length;                  \
  using glm::log;                     \
  using glm::max;                     \
  using glm::min;                     \
  using glm::normalize;               \
  using glm::pow;                     \
  using glm::reflect;                 \
  using glm::sin;                     \
  using glm::sqrt;

namespace facet::materials {

namespace f64 {
using real = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
FACET_MATERIALS_GLSL_BUILTINS
#include "materials/shading/common.h"
#include "materials/shading/microfacet.h"
#include "materials/shading/fresnel.h"
#include "materials/shading/brdf.h"
#include "materials/shading/sampling.h"
const real INFINITE_DISTANCE = std::numeric_limits<real>::infinity();
#include "compute/shared/lights.h"
}  // namespace f64

namespace f32 {
using real = float;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
FACET_MATERIALS_GLSL_BUILTINS
#include "materials/shading/common.h"
#include "materials/shading/microfacet.h"
#include "materials/shading/fresnel.h"
#include "materials/shading/brdf.h"
#include "materials/shading/sampling.h"
const real INFINITE_DISTANCE = std::numeric_limits<real>::infinity();
#include "compute/shared/lights.h"
}  // namespace f32

}  // namespace facet::materials

#undef FACET_MATERIALS_GLSL_BUILTINS
#undef FACET_FN
