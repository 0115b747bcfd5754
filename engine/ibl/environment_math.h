// C++ side of the image-based-lighting headers of compute/shared/ and of
// compute/shared/random.h, instantiated next to the shading models they build
// on: facet::materials::f64 (the CPU reference) and facet::materials::f32
// (what the GPU computes, for tests). Kernels include the same headers, in
// this order, after materials/shading.glsl.
#pragma once

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include <cmath>
#include <cstdint>

#include "materials/shading.h"

#define FACET_FN inline

// What the shared source needs beyond materials/shading.h's built-ins:
// GLSL's 32-bit uint and uvec2, two-argument atan and floor.
#define FACET_ENVIRONMENT_GLSL_BUILTINS                         \
  using uint = std::uint32_t;                                   \
  using uvec2 = glm::uvec2;                                     \
  inline real atan(real y, real x) { return std::atan2(y, x); } \
  using glm::floor;

namespace facet::materials {

namespace f64 {
FACET_ENVIRONMENT_GLSL_BUILTINS
#include "compute/shared/environment_mapping.h"
#include "compute/shared/mis.h"
#include "compute/shared/lobe_sampling.h"
#include "compute/shared/split_sum.h"
#include "compute/shared/low_discrepancy.h"
#include "compute/shared/dfg.h"
#include "compute/shared/spherical_harmonics.h"
#include "compute/shared/irradiance_map.h"
#include "compute/shared/prefilter.h"
#include "compute/shared/random.h"
#include "compute/shared/scrambled_net.h"
#include "compute/shared/sampled_environment.h"
#include "compute/shared/filtered_environment.h"
}  // namespace f64

namespace f32 {
FACET_ENVIRONMENT_GLSL_BUILTINS
#include "compute/shared/environment_mapping.h"
#include "compute/shared/mis.h"
#include "compute/shared/lobe_sampling.h"
#include "compute/shared/split_sum.h"
#include "compute/shared/low_discrepancy.h"
#include "compute/shared/dfg.h"
#include "compute/shared/spherical_harmonics.h"
#include "compute/shared/irradiance_map.h"
#include "compute/shared/prefilter.h"
#include "compute/shared/random.h"
#include "compute/shared/scrambled_net.h"
#include "compute/shared/sampled_environment.h"
#include "compute/shared/filtered_environment.h"
}  // namespace f32

}  // namespace facet::materials

#undef FACET_ENVIRONMENT_GLSL_BUILTINS
#undef FACET_FN
