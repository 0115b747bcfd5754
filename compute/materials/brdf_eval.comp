// Evaluates the shared BRDF source on the GPU, for comparing GLSL float with
// the C++ double reference (facet::rules::f64) case by case; building it
// is also the check that materials/shading/*.h compile as GLSL.
//
// Specialization constants 0, 1, 2: d_model, g_model, f_model (ids of
// rules/shading/microfacet.h and fresnel.h), so that each variant only
// keeps its own branches. std430 buffers of vec4 (w of inputs unused):
//   binding 0, read:  Case   { vec4 n; vec4 l; vec4 v; }
//   binding 1, write: Result { vec4 f_D;   xyz = f, w = D
//                              vec4 F_G;   xyz = F, w = G
//                              vec4 pdf; } x = cosine, y = D-proportional, z = GGX visible
// binding 2, uniform: vec4 f0_alpha (w = alpha), vec4 eta, vec4 k, vec4 diffuse,
// uint count.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "rules/language.glsl"
#include "rules/shading/brdf.h"
#include "rules/shading/brdf_sampling.h"

layout(local_size_x = 64) in;

layout(constant_id = 0) const int D_MODEL = 0;
layout(constant_id = 1) const int G_MODEL = 4;
layout(constant_id = 2) const int F_MODEL = 1;

struct Case {
  vec4 n;
  vec4 l;
  vec4 v;
};

struct Result {
  vec4 f_D;
  vec4 F_G;
  vec4 pdf;
};

layout(set = 0, binding = 0, std430) readonly buffer Cases { Case cases[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Results { Result results[]; };

layout(set = 0, binding = 2, std140) uniform Parameters {
  vec4 f0_alpha;
  vec4 eta;
  vec4 k;
  vec4 diffuse;
  vec4 tangent_anisotropy;  // xyz the tangent, w the anisotropy
  uint count;
} parameters;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= parameters.count) return;
  BrdfParams p;
  p.d_model = D_MODEL;
  p.g_model = G_MODEL;
  p.f_model = F_MODEL;
  p.alpha = parameters.f0_alpha.w;
  p.f0 = parameters.f0_alpha.xyz;
  p.eta = parameters.eta.xyz;
  p.k = parameters.k.xyz;
  p.metallic = 0.0;
  p.diffuse = parameters.diffuse.xyz;
  p.anisotropy = parameters.tangent_anisotropy.w;
  p.tangent = parameters.tangent_anisotropy.xyz;
  p.clearcoat = 0.0;  // the coat is tested through the rules' C++ instantiation
  p.clearcoat_alpha = 0.0;
  vec3 n = cases[i].n.xyz;
  p.clearcoat_normal = n;
  p.sheen_color = vec3(0.0);  // the sheen likewise
  p.sheen_alpha = 0.0;
  p.sheen_albedo_near = vec4(0.0);
  p.sheen_albedo_far = vec4(0.0);
  p.iridescence = 0.0;
  p.iridescence_ior = 1.0;
  p.iridescence_thickness = 0.0;
  vec3 l = cases[i].l.xyz;
  vec3 v = cases[i].v.xyz;
  BrdfTerms t = brdf_terms(p, n, l, v);
  results[i].f_D = vec4(t.value, t.D);
  results[i].F_G = vec4(t.F, t.G);
  results[i].pdf = vec4(direction_pdf(SAMPLE_COSINE, p, n, l, v), direction_pdf(SAMPLE_D, p, n, l, v),
                        direction_pdf(SAMPLE_GGX_VISIBLE, p, n, l, v), 0.0);
}
