// C++ side of the shared shading source. The headers in materials/shading/
// are written in the common subset of GLSL and C++; materials/shading_instance.h
// gives them GLM types and GLSL's built-ins, and this file instantiates them
// twice:
//   facet::materials::f64  double, the CPU reference
//   facet::materials::f32  float, what the GPU computes (for tests and the
//                          float-vs-double table)
// GLSL shaders include materials/shading.glsl instead.
#pragma once

#include <glm/geometric.hpp>
#include <glm/glm.hpp>

#include <limits>

#define FACET_FN inline

namespace facet::materials {

namespace f64 {
#define FACET_REAL double
#include "materials/shading_instance.h"
}  // namespace f64

namespace f32 {
#define FACET_REAL float
#include "materials/shading_instance.h"
}  // namespace f32

}  // namespace facet::materials
#undef FACET_FN
