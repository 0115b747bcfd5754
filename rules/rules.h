// The one C++ instantiation of the rules both backends apply. The headers
// below rules/ are written once, in the subset of GLSL and C++ that
// rules/language.h describes; this file compiles every one of them twice:
//   facet::rules::f64  double: the CPU reference
//   facet::rules::f32  float: what the GPU computes, for the host code that
//                      must agree with a kernel and for the float-vs-double
//                      tests
// Kernels include rules/language.glsl and the rules they use instead.
#pragma once

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/glm.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#define FACET_FN inline
#define FACET_OUT(type) type&
#define FACET_PRECISE

namespace facet::rules {

namespace f64 {
#define FACET_REAL double
#include "rules/instance.h"
}  // namespace f64

namespace f32 {
#define FACET_REAL float
#include "rules/instance.h"
}  // namespace f32

}  // namespace facet::rules

#undef FACET_PRECISE
#undef FACET_OUT
#undef FACET_FN
