// C++ side of compute/shared/sample_plan.h, in double for the CPU reference
// (the GPU backend's host code takes only its integer rules from it).
#pragma once

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vec2.hpp>

#include <cstdint>

namespace facet::camera {

using uint = std::uint32_t;
using real = double;
using vec2 = glm::dvec2;
using glm::floor;
using glm::sqrt;
#define FACET_FN inline
#include "compute/shared/sample_plan.h"
#undef FACET_FN

}  // namespace facet::camera
