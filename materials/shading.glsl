// GLSL side of the shared shading source (C++ side: materials/shading.h).
// A compute shader uses it with
//   #extension GL_GOOGLE_include_directive : require
//   #include "materials/shading.glsl"
// (glslang -I<repo root>), then calls brdf_terms / brdf_evaluate /
// sample_direction / direction_pdf; model ids are best fed from
// specialization constants so that only the chosen branches survive.
#ifndef FACET_MATERIALS_SHADING_GLSL
#define FACET_MATERIALS_SHADING_GLSL

#define real float
#define FACET_FN

#include "materials/shading/common.h"
#include "materials/shading/microfacet.h"
#include "materials/shading/fresnel.h"
#include "materials/shading/brdf.h"
#include "materials/shading/sampling.h"

#endif
