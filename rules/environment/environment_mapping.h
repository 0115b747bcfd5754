// The equirectangular map's geometry, its directions, texel solid angles and
// bilinear taps (docs/rendering.md, "Image-based lighting").
//   u = 1/2 + atan2(d.x, -d.z) / (2 pi)   (u = 1/2 looks down -z)
//   v = acos(d.y) / pi                      (v = 0 is +y, row 0 of the map)

#ifndef FACET_RULE_ENVIRONMENT_ENVIRONMENT_MAPPING
#define FACET_RULE_ENVIRONMENT_ENVIRONMENT_MAPPING

#include "rules/math.h"

// World direction -> map frame: the map is turned by `rotation` (given as
// its cosine and sine) about +y, so the world sees R d_map; undo it.
FACET_FN vec3 environment_to_map(vec3 d, real cos_rotation, real sin_rotation) {
  return vec3(cos_rotation * d.x - sin_rotation * d.z, d.y, sin_rotation * d.x + cos_rotation * d.z);
}

FACET_FN vec3 environment_from_map(vec3 d, real cos_rotation, real sin_rotation) {
  return vec3(cos_rotation * d.x + sin_rotation * d.z, d.y, -sin_rotation * d.x + cos_rotation * d.z);
}

// theta from atan2 rather than acos(d.y): well conditioned at the poles,
// and lavapipe's acos is far less accurate than its atan. At a pole every
// longitude is the same direction; GLSL leaves atan(0, 0) undefined and C++
// takes it from the zeros' signs, so both read u = 1/2 there.
FACET_FN vec2 environment_uv(vec3 d) {
  bool pole = d.x == real(0) && d.z == real(0);
  real u = pole ? real(0.5) : real(0.5) + atan(d.x, -d.z) * (real(0.5) * INV_PI);
  real v = atan(sqrt(d.x * d.x + d.z * d.z), d.y) * INV_PI;
  return vec2(u, v);
}

FACET_FN vec3 environment_direction(vec2 uv) {
  real phi = real(2) * PI * (uv.x - real(0.5));
  real cos_theta = cos(PI * uv.y);
  real sin_theta = sin(PI * uv.y);
  return vec3(sin_theta * sin(phi), cos_theta, -sin_theta * cos(phi));
}

// The direction with polar cosine `cos_theta` at longitude u (sampling
// draws cos theta uniformly within a row, so the density is constant per
// unit solid angle inside each texel).
FACET_FN vec3 environment_direction_cos(real u, real cos_theta) {
  real phi = real(2) * PI * (u - real(0.5));
  real sin_theta = sqrt(max(real(1) - cos_theta * cos_theta, real(0)));
  return vec3(sin_theta * sin(phi), cos_theta, -sin_theta * cos(phi));
}

FACET_FN real environment_row_cos(int y, int height) { return cos(PI * real(y) / real(height)); }

// (2 pi / W)(cos theta_top - cos theta_bottom): the texels' solid angles sum
// to 4 pi exactly.
FACET_FN real environment_texel_solid_angle(int y, int width, int height) {
  return real(2) * PI / real(width) * (environment_row_cos(y, height) - environment_row_cos(y + 1, height));
}

// Bilinear footprint of a lookup at uv: texel columns x0, x1 (wrapping),
// rows y0, y1 (clamped at the poles) and the weights of x1 and y1.
struct BilinearTaps {
  int x0;
  int x1;
  int y0;
  int y1;
  real fx;
  real fy;
};

FACET_FN BilinearTaps environment_bilinear(vec2 uv, int width, int height) {
  real x = uv.x * real(width) - real(0.5);
  real y = clamp(uv.y * real(height) - real(0.5), real(0), real(height - 1));
  real xf = floor(x);
  real yf = floor(y);
  BilinearTaps b;
  b.fx = x - xf;
  b.fy = y - yf;
  int xi = int(xf);  // >= -1: uv.x >= 0
  b.x0 = xi < 0 ? xi + width : xi % width;
  b.x1 = (b.x0 + 1) % width;
  b.y0 = int(yf);
  b.y1 = min(b.y0 + 1, height - 1);
  return b;
}

#endif
