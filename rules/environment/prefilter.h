// The prefiltered levels by filtered importance sampling (Krivanek & Colbert
// 2008) with n = v = r, read from a solid-angle-weighted mip chain of the map
// (docs/rendering.md, "Prefiltered: the split sum").

#ifndef FACET_RULE_ENVIRONMENT_PREFILTER
#define FACET_RULE_ENVIRONMENT_PREFILTER

#include "rules/environment/environment_mapping.h"
#include "rules/math.h"
#include "rules/sampling/low_discrepancy.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/domain.h"
#include "rules/shading/microfacet.h"

// A coarser texel of the mip chain averages the 2 x 2 finer texels it covers
// weighted by solid angle, so that the chain keeps the map's integral over
// the sphere: the finer row on top (nearer the pole) has this share of the
// pair's solid angle.
FACET_FN real environment_upper_row_share(int coarser_row, int finer_height) {
  real top = environment_row_cos(2 * coarser_row, finer_height);
  real middle = environment_row_cos(2 * coarser_row + 1, finer_height);
  real bottom = environment_row_cos(2 * coarser_row + 2, finer_height);
  return (top - middle) / (top - bottom);
}

// Sample i of n: a GGX half vector in r's local frame; l = reflect(-r, m)
// has n.l = 2 (n.m)^2 - 1.
FACET_FN vec3 prefilter_sample_normal(int i, int n, real alpha) {
  return sample_microfacet_normal(D_GGX, effective_alpha(alpha), hammersley_point(i, n));
}

// With half vectors drawn from D(m)(n.m), f (n.l) / pdf(l) is G(l, n): weighing
// by GGX's height-correlated G makes the split sum exact wherever v = n.
FACET_FN real prefilter_sample_weight(real alpha, vec3 m) {
  real nl = real(2) * m.z * m.z - real(1);
  if (nl <= real(0)) return real(0);
  return microfacet_G(G_SMITH_GGX_CORRELATED, effective_alpha(alpha), nl, real(1), m.z, m.z);
}

// Level of the mip chain a sample of density `pdf` (per unit solid angle),
// one of `samples`, reads: where a texel is as large as the solid angle the
// sample stands for, Omega_s = 1 / (samples pdf), moved by `offset` levels
// (Krivanek & Colbert 2008, eq. 13, where the offset is 1). Omega_p is the
// mean texel solid angle: equirectangular texels shrink only in azimuth
// towards the poles, and the chain blurs their polar extent.
FACET_FN real mip_level_for_density(real pdf, int samples, int width, int height, int chain_levels, real offset) {
  if (pdf <= real(0)) return real(chain_levels - 1);
  real omega_s = real(1) / (real(samples) * pdf);
  real omega_p = real(4) * PI / (real(width) * real(height));
  // 0.5 log2(x) as log(x) / (2 ln 2): C++ and GLSL share log, not log2.
  real lod = real(0.72134752044448170368) * log(omega_s / omega_p) + offset;
  return clamp(lod, real(0), real(chain_levels - 1));
}

// The prefilter's samples: half vectors drawn from D(m)(n.m) with n = v = r,
// so that pdf(l) = D(m) / 4, read one level coarser because a box is
// narrower than the lobe it stands in for.
FACET_FN real prefilter_source_lod(real alpha, vec3 m, int samples, int width, int height, int chain_levels) {
  real pdf = real(0.25) * microfacet_D(D_GGX, effective_alpha(alpha), m.z, m.x * m.x + m.y * m.y);
  return mip_level_for_density(pdf, samples, width, height, chain_levels, real(1));
}

#endif
