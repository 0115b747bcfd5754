// The real spherical harmonics of bands 0-2 and the exact integrals over a map
// texel that project the environment onto them (Ramamoorthi & Hanrahan 2001;
// docs/rendering.md, "Prefiltered: the split sum").

#ifndef FACET_RULE_ENVIRONMENT_SPHERICAL_HARMONICS
#define FACET_RULE_ENVIRONMENT_SPHERICAL_HARMONICS

#include "rules/math.h"

// The basis at unit d.
FACET_FN real sh_basis(int i, vec3 d) {
  switch (i) {
    case 0:
      return real(0.282094791773878);
    case 1:
      return real(0.488602511902920) * d.y;
    case 2:
      return real(0.488602511902920) * d.z;
    case 3:
      return real(0.488602511902920) * d.x;
    case 4:
      return real(1.092548430592079) * d.x * d.y;
    case 5:
      return real(1.092548430592079) * d.y * d.z;
    case 6:
      return real(0.315391565252520) * (real(3) * d.z * d.z - real(1));
    case 7:
      return real(1.092548430592079) * d.x * d.z;
    case 8:
      return real(0.546274215296340) * (d.x * d.x - d.y * d.y);
  }
  return real(0);
}

// Convolving radiance with the clamped cosine scales band l by A_l; divided
// by pi here so that the result times c_diff is the Lambertian radiance.
FACET_FN real sh_cosine_band(int i) {
  if (i == 0) return real(1);
  if (i < 4) return real(2) / real(3);
  return real(0.25);
}

// Azimuthal integrals over texel column x of a width-wide map of 1, sin phi,
// cos phi, cos^2 phi and sin phi cos phi (phi = 2 pi (u - 1/2)): every basis
// function is one of these times a polynomial in cos theta and sin theta,
// so a texel's SH integral is a column integral times a row integral.
// Written from the column's centre and half width so that no two nearby
// sines are subtracted.
struct ShColumnIntegrals {
  real one;
  real sin_phi;
  real cos_phi;
  real cos2_phi;
  real sin_cos_phi;
};

FACET_FN ShColumnIntegrals sh_column_integrals(int x, int width) {
  real width_phi = real(2) * PI / real(width);
  real centre = width_phi * (real(x) + real(0.5)) - PI;
  real half_chord = real(2) * sin(real(0.5) * width_phi);
  real chord = sin(width_phi);
  ShColumnIntegrals c;
  c.one = width_phi;
  c.sin_phi = half_chord * sin(centre);
  c.cos_phi = half_chord * cos(centre);
  c.cos2_phi = real(0.5) * (width_phi + chord * cos(real(2) * centre));
  c.sin_cos_phi = real(0.5) * chord * sin(real(2) * centre);
  return c;
}

#endif
