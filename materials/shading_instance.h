// One instantiation of the shared shading headers for the scalar type
// FACET_REAL, inside the includer's namespace (materials/shading.h includes
// it once per type). No include guard on purpose.
using real = FACET_REAL;
using vec2 = glm::vec<2, real>;
using vec3 = glm::vec<3, real>;
using glm::abs;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::inversesqrt;
using glm::length;
using glm::log;
using glm::max;
using glm::min;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::sin;
using glm::sqrt;
const real INFINITE_DISTANCE = std::numeric_limits<real>::infinity();
#include "materials/shading/common.h"
#include "materials/shading/microfacet.h"
#include "materials/shading/fresnel.h"
#include "materials/shading/brdf.h"
#include "materials/shading/sampling.h"
#include "materials/shading/lights.h"
#undef FACET_REAL
