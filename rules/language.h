// The C++ side of the language the rules are written in: the subset of GLSL
// and C++ that reads the same in both (rules/language.glsl is the GLSL side).
// The rules of the subset:
//   - the scalar type is `real`; literals are typed (`real(0.5)`), so the
//     float instantiation really computes in float;
//   - `uint` is 32 bits on both sides, and its arithmetic wraps alike;
//   - a function is declared `FACET_FN`; an output parameter is
//     `FACET_OUT(type) name` (a reference in C++, `out` in GLSL), the way
//     OpenSubdiv's osd/patchBasisCommon*.h spell one source for every language;
//   - a value whose rounding must not change by fusing a multiply and an add
//     is declared `FACET_PRECISE` (GLSL's `precise`; C++ as built here
//     targets no fused multiply-add);
//   - no other references, no constructors of structs, no C++-only syntax;
//   - a rule includes the rules it uses, and nothing else, inside the guard
//       #ifndef FACET_RULE_<PATH>
//       #define FACET_RULE_<PATH>
//       ...
//       #endif
//     <PATH> being its path below rules/ without `.h`, in capitals with `_`
//     for `/`: rules/shading/brdf.h is FACET_RULE_SHADING_BRDF. A kernel has
//     one instantiation; C++ has one per real type, each in its own namespace,
//     so rules/instance.h undefines every guard after each.
// This file is that per-type part: it is included inside the namespace, with
// FACET_REAL naming the scalar type, and maps GLSL's types and built-ins onto
// GLM and the C++ library.
using real = FACET_REAL;
using uint = std::uint32_t;
using vec2 = glm::vec<2, real>;
using vec3 = glm::vec<3, real>;
using vec4 = glm::vec<4, real>;
using uvec2 = glm::uvec2;
using ivec3 = glm::ivec3;
using uvec3 = glm::uvec3;
using glm::abs;
using glm::ceil;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::floor;
using glm::inversesqrt;
using glm::length;
using glm::log;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::sin;
using glm::sqrt;
// GLSL's two-argument atan is C++'s atan2; the one-argument form is GLM's.
using glm::atan;
inline real atan(real y, real x) { return std::atan2(y, x); }
const real INFINITE_DISTANCE = std::numeric_limits<real>::infinity();
