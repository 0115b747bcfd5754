// C++ side of compute/shared/texture_sampling.h and textured_material.h,
// instantiated beside the shading models they build on:
// facet::materials::f64 (the CPU reference) and facet::materials::f32 (what
// the GPU computes, for tests).
#pragma once

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include <cstdint>

#include "materials/shading.h"

#define FACET_FN inline

#define FACET_TEXTURE_GLSL_BUILTINS \
  using uint = std::uint32_t;       \
  using glm::atan;                  \
  using glm::ceil;                  \
  using glm::floor;                 \
  using glm::mix;

namespace facet::materials {

namespace f64 {
FACET_TEXTURE_GLSL_BUILTINS
#include "compute/shared/texture_sampling.h"
#include "compute/shared/textured_material.h"
}  // namespace f64

namespace f32 {
FACET_TEXTURE_GLSL_BUILTINS
#include "compute/shared/texture_sampling.h"
#include "compute/shared/textured_material.h"
}  // namespace f32

}  // namespace facet::materials

#undef FACET_TEXTURE_GLSL_BUILTINS
#undef FACET_FN
