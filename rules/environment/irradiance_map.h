// The split sum's cosine-convolved irradiance map, what the SH irradiance gives
// way to where a bright source makes bands 0-2 ring (docs/rendering.md,
// "Prefiltered: the split sum").

#ifndef FACET_RULE_ENVIRONMENT_IRRADIANCE_MAP
#define FACET_RULE_ENVIRONMENT_IRRADIANCE_MAP

#include "rules/environment/environment_mapping.h"

// The irradiance table, at FrameParams::shOffset of the environment tables:
// texel 0 holds (source, width, height) of the map, texels 1-9 the SH
// coefficients, then the map's texels row by row.
const int IRRADIANCE_FROM_SH = 0;
const int IRRADIANCE_FROM_MAP = 1;

FACET_FN int irradiance_sh_texel(int i) { return 1 + i; }

FACET_FN int irradiance_map_texel(int texel) { return 10 + texel; }

// The map's nodes: columns at texel centres, u = (x + 1/2) / width, and
// rows from pole to pole, v = y / (rows - 1), so that its first and last
// rows are the poles themselves. Every node of a pole row is the same
// direction, so a lookup near a pole tends to one value whatever the
// azimuth, which a normal at a pole does not define (the flat top of a
// cube, a floor): rows of texel centres there would read two points
// of a ring a few degrees away, and the float and double azimuths of the
// same normal would pick different points.
FACET_FN vec3 irradiance_node_direction(int x, int y, int width, int rows) {
  return environment_direction(vec2((real(x) + real(0.5)) / real(width), real(y) / real(rows - 1)));
}

// The band of directions a row of nodes stands for, per node: the solid
// angle between the half-way latitudes to its neighbouring rows.
FACET_FN real irradiance_node_solid_angle(int y, int width, int rows) {
  real above = max(real(y) - real(0.5), real(0)) / real(rows - 1);
  real below = min(real(y) + real(0.5), real(rows - 1)) / real(rows - 1);
  return real(2) * PI / real(width) * (cos(PI * above) - cos(PI * below));
}

// Bilinear taps of the map's nodes at uv, as indices y * width + x.
struct IrradianceTaps {
  int t00;  // (x0, y0)
  int t10;  // (x1, y0)
  int t01;  // (x0, y1)
  int t11;  // (x1, y1)
  real fx;  // the weights of x1 and y1
  real fy;
};

FACET_FN IrradianceTaps irradiance_map_taps(vec2 uv, int width, int rows) {
  real x = uv.x * real(width) - real(0.5);
  real y = clamp(uv.y, real(0), real(1)) * real(rows - 1);
  real xf = floor(x);
  int x0 = int(xf);  // >= -1: uv.x >= 0
  x0 = x0 < 0 ? x0 + width : x0 % width;
  int x1 = (x0 + 1) % width;
  int y0 = min(int(y), rows - 2);
  IrradianceTaps t;
  t.t00 = y0 * width + x0;
  t.t10 = y0 * width + x1;
  t.t01 = (y0 + 1) * width + x0;
  t.t11 = (y0 + 1) * width + x1;
  t.fx = x - xf;
  t.fy = y - real(y0);
  return t;
}

// Source texel (x, y) of a width x height map weighs n.l at its centre
// times its solid angle in the cosine-weighted mean of the radiance around
// n, a node's direction. The mean over these weights is E(n) / pi, exact
// for a constant map.
FACET_FN vec3 irradiance_texel_direction(int x, int y, int width, int height) {
  return environment_direction(vec2((real(x) + real(0.5)) / real(width), (real(y) + real(0.5)) / real(height)));
}

FACET_FN real irradiance_texel_weight(vec3 n, vec3 texel_direction, real solid_angle) {
  return max(dot(n, texel_direction), real(0)) * solid_angle;
}

// The finest level of a chain (each level half the one before) at most
// 128 texels wide that the convolution reads, or the chain's last.
FACET_FN int irradiance_source_level(int width, int levels) {
  int level = 0;
  while (level + 1 < levels && width > 128) {
    width /= 2;
    ++level;
  }
  return level;
}

#endif
