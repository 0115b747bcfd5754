// Thin-film interference over a surface (KHR_materials_iridescence): the
// reflectance of a film of index `film_ior` and thickness `thickness_nm` on
// a base whose Fresnel at normal incidence is `base_f0`, in linear Rec. 709
// RGB, after Belcour & Barla 2017, "A Practical Extension to Microfacet
// Theory for the Modeling of Varying Iridescence" (docs/shading.md,
// "Iridescence").

#ifndef FACET_RULE_SHADING_THIN_FILM
#define FACET_RULE_SHADING_THIN_FILM

#include "rules/math.h"
#include "rules/shading/fresnel.h"

// The index of a dielectric whose Fresnel at normal incidence is f0, seen
// from air (f0 kept below 1, which no index gives).
FACET_FN vec3 ior_of_f0(vec3 f0) {
  vec3 root = sqrt(clamp(f0, vec3(real(0)), vec3(real(0.9999))));
  return (vec3(real(1)) + root) / (vec3(real(1)) - root);
}

// Fresnel at normal incidence between indices a and b.
FACET_FN vec3 f0_between(vec3 a, vec3 b) {
  vec3 r = (a - b) / (a + b);
  return r * r;
}

// The CIE XYZ colour-matching functions' Fourier transforms at optical path
// difference `opd` (nm) with phase `shift`, each fitted by Gaussians
// (Belcour & Barla 2017, supplemental: their amplitudes, centres and
// variances, here in nanometres and normalized to Y's integral), taken to
// linear Rec. 709 RGB (IEC 61966-2-1's matrix).
FACET_FN vec3 interference_spectrum(real opd, vec3 shift) {
  vec3 xyz =
      vec3(real(0.8465900023036574), real(1.0002218935839293), real(1.0011224857215686)) *
      cos(vec3(real(0.010562034501368885), real(0.011280202581979511), real(0.013875786432375399)) * opd + shift) *
      exp(-vec3(real(1.708546957081381e-07), real(3.6733088444150414e-07), real(2.6103524504177177e-07)) * sqr(opd));
  xyz.x += real(0.15386830651283523) * cos(real(0.014073706769551556) * opd + shift.x) *
           exp(real(-1.7876617059605132e-07) * sqr(opd));
  return vec3(dot(vec3(real(3.2404542), real(-1.5371385), real(-0.4985314)), xyz),
              dot(vec3(real(-0.9692660), real(1.8760108), real(0.0415560)), xyz),
              dot(vec3(real(0.0556434), real(-0.2040259), real(1.0572252)), xyz));
}

// The film's reflectance seen from air at cos_i to the facet normal: the
// Airy sum of the waves the film's two interfaces reflect, each
// interface's Fresnel Schlick's of its indices, the sum's first two
// harmonics integrated against the eye's response; total internal
// reflection in the film reflects everything. Each channel in [0, 1]: the
// spectral fit leaves the gamut slightly, which the clamp removes.
FACET_FN vec3 thin_film_fresnel(real cos_i, real film_ior, real thickness_nm, vec3 base_f0) {
  real c1 = clamp(cos_i, real(0), real(1));
  real eta2 = film_ior;
  real cos2_sq = real(1) - (real(1) - sqr(c1)) / sqr(eta2);
  if (cos2_sq <= real(0)) return vec3(real(1));
  real c2 = sqrt(cos2_sq);
  // Air to film: reflected R12, transmitted there and back T121; a wave
  // reflected off a denser medium turns by pi.
  real r12 = fresnel_schlick(vec3(sqr((eta2 - real(1)) / (eta2 + real(1)))), c1).x;
  real t121 = real(1) - r12;
  real phi21 = eta2 < real(1) ? real(0) : PI;
  // Film to base, per channel.
  vec3 eta3 = ior_of_f0(base_f0);
  vec3 r23 = fresnel_schlick(f0_between(eta3, vec3(eta2)), c2);
  vec3 phi23 = vec3(eta3.x < eta2 ? PI : real(0), eta3.y < eta2 ? PI : real(0), eta3.z < eta2 ? PI : real(0));
  real opd = real(2) * eta2 * thickness_nm * c2;
  vec3 phi = vec3(phi21) + phi23;
  vec3 r123 = clamp(r12 * r23, vec3(real(1e-5)), vec3(real(0.9999)));
  vec3 rs = sqr(t121) * r23 / (vec3(real(1)) - r123);
  vec3 reflectance = vec3(r12) + rs;
  vec3 harmonic = rs - vec3(t121);
  for (int m = 1; m <= 2; ++m) {
    harmonic *= sqrt(r123);
    reflectance += harmonic * real(2) * interference_spectrum(real(m) * opd, real(m) * phi);
  }
  return clamp(reflectance, vec3(real(0)), vec3(real(1)));
}

#endif
