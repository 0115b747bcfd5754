// C++ side of compute/shared/sample_plan.h and camera_samples.h, in double
// for the CPU reference (the GPU backend's host code takes only the integer
// rules from it), with the scrambled net they place the samples by.
#pragma once

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec2.hpp>

#include <cstdint>

namespace facet::camera {

using uint = std::uint32_t;
using real = double;
using vec2 = glm::dvec2;
using uvec2 = glm::uvec2;
using glm::floor;
using glm::sqrt;
#define FACET_FN inline
#include "compute/shared/sample_plan.h"
#include "compute/shared/random.h"
#include "compute/shared/low_discrepancy.h"
#include "compute/shared/scrambled_net.h"
#include "compute/shared/camera_samples.h"
#undef FACET_FN

}  // namespace facet::camera
