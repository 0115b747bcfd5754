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

// Bilinear taps of the map at uv, as texel indices y * width + x, continued
// across the poles: the row beyond a pole is its first row half a turn
// round (width is even). Clamping there instead would read a normal at the
// pole from one side of a ring half a texel away.
struct IrradianceTaps {
  int t00;  // (x0, y0)
  int t10;  // (x1, y0)
  int t01;  // (x0, y1)
  int t11;  // (x1, y1)
  real fx;  // the weights of x1 and y1
  real fy;
};

FACET_FN IrradianceTaps irradiance_map_taps(vec2 uv, int width, int height) {
  real x = uv.x * real(width) - real(0.5);
  real y = clamp(uv.y * real(height) - real(0.5), real(-0.5), real(height) - real(0.5));
  real xf = floor(x);
  real yf = floor(y);
  int x0 = int(xf);  // >= -1: uv.x >= 0
  x0 = x0 < 0 ? x0 + width : x0 % width;
  int x1 = (x0 + 1) % width;
  int y0 = int(yf);
  int y1 = y0 + 1;
  int top_turn = y0 < 0 ? width / 2 : 0;
  int bottom_turn = y1 >= height ? width / 2 : 0;
  int top = max(y0, 0) * width;
  int bottom = min(y1, height - 1) * width;
  IrradianceTaps t;
  t.t00 = top + (x0 + top_turn) % width;
  t.t10 = top + (x1 + top_turn) % width;
  t.t01 = bottom + (x0 + bottom_turn) % width;
  t.t11 = bottom + (x1 + bottom_turn) % width;
  t.fx = x - xf;
  t.fy = y - yf;
  return t;
}

// Source texel (x, y) of a width x height map weighs n.l at its centre
// times its solid angle in the cosine-weighted mean of the radiance around
// n. The mean over these weights is E(n) / pi, exact for a constant map.
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
