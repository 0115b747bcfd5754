// Bicubic Bézier / Gregory patches in float (the same formulas as
// scenes/bezier_patch.h). The including kernel declares the texel buffer
// `patchPoints` (compute/layout/patch_records.h).
#ifndef FACET_RAYCAST_PATCH_EVAL_GLSL
#define FACET_RAYCAST_PATCH_EVAL_GLSL

// A patch's control points as one 4x4 matrix per coordinate, [i][j] the
// point in column i (along s) and row j (along t): evaluation and
// restriction become matrix products, and nothing is indexed at run time.
// A Gregory patch adds the alternates of its interior slots 5, 6, 10, 9,
// i.e. (i, j) = (1, 1), (2, 1), (2, 2), (1, 2). The points are relative to
// `anchor` (compute/layout/patch_records.h): positions add it, derivatives
// and restrictions need only the points.
struct ControlPoints {
  mat4 x;
  mat4 y;
  mat4 z;
  mat4x3 alternates;
  vec3 anchor;
  bool gregory;
};

vec3 patch_point(uint index) { return texelFetch(patchPoints, int(index)).xyz; }

ControlPoints load_control_points(uint firstPoint, uint kind) {
  ControlPoints c;
  c.anchor = patch_point(firstPoint);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      vec3 p = i + j == 0 ? vec3(0.0) : patch_point(firstPoint + uint(4 * j + i));
      c.x[i][j] = p.x;
      c.y[i][j] = p.y;
      c.z[i][j] = p.z;
    }
  }
  c.gregory = kind == FACET_PATCH_GREGORY;
  c.alternates = mat4x3(0.0);
  if (c.gregory)
    for (int k = 0; k < 4; ++k) c.alternates[k] = patch_point(firstPoint + 16u + uint(k));
  return c;
}

vec3 control_point(ControlPoints c, int i, int j) { return vec3(c.x[i][j], c.y[i][j], c.z[i][j]); }

void set_control_point(inout ControlPoints c, int i, int j, vec3 p) {
  c.x[i][j] = p.x;
  c.y[i][j] = p.y;
  c.z[i][j] = p.z;
}

float blend_ratio(float a, float b) { return a + b > 0.0 ? a / (a + b) : 0.5; }

// Weight of the primary point of each interior slot at (s, t).
vec4 primary_weights(float s, float t) {
  return vec4(blend_ratio(s, t), blend_ratio(t, 1.0 - s), blend_ratio(1.0 - s, 1.0 - t), blend_ratio(1.0 - t, s));
}

// d(a / (a + b)) for a, b affine in (s, t) with gradients da, db.
vec2 ratio_gradient(float a, float b, vec2 da, vec2 db) {
  float sum = a + b;
  if (!(sum > 0.0)) return vec2(0.0);
  return (b * da - a * db) / (sum * sum);
}

vec4 bernstein(float x) {
  float y = 1.0 - x;
  return vec4(y * y * y, 3.0 * y * y * x, 3.0 * y * x * x, x * x * x);
}

vec4 bernstein_derivative(float x) {
  float y = 1.0 - x;
  return vec4(-3.0 * y * y, 3.0 * y * y - 6.0 * y * x, 6.0 * y * x - 3.0 * x * x, 3.0 * x * x);
}

struct PatchSample {
  vec3 position;
  vec3 ds;
  vec3 dt;
};

// The Bézier points with each Gregory interior slot blended: weight w[k] on
// its primary point, the rest on its alternate.
ControlPoints pinned(ControlPoints c, vec4 w) {
  set_control_point(c, 1, 1, mix(c.alternates[0], control_point(c, 1, 1), w[0]));
  set_control_point(c, 2, 1, mix(c.alternates[1], control_point(c, 2, 1), w[1]));
  set_control_point(c, 2, 2, mix(c.alternates[2], control_point(c, 2, 2), w[2]));
  set_control_point(c, 1, 2, mix(c.alternates[3], control_point(c, 1, 2), w[3]));
  return c;
}

// sum_ij a_i b_j P_ij, per coordinate.
vec3 tensor(ControlPoints c, vec4 a, vec4 b) { return vec3(dot(b, c.x * a), dot(b, c.y * a), dot(b, c.z * a)); }

PatchSample evaluate_patch(ControlPoints c, float s, float t) {
  vec4 bs = bernstein(s), bt = bernstein(t);
  vec4 ds = bernstein_derivative(s), dt = bernstein_derivative(t);
  ControlPoints p = c.gregory ? pinned(c, primary_weights(s, t)) : c;
  PatchSample result;
  result.position = c.anchor + tensor(p, bs, bt);
  result.ds = tensor(p, ds, bt);
  result.dt = tensor(p, bs, dt);
  if (c.gregory) {
    // The interior points move with (s, t): add B * d(blend) for each.
    vec2 g0 = ratio_gradient(s, t, vec2(1, 0), vec2(0, 1));
    vec2 g1 = ratio_gradient(t, 1.0 - s, vec2(0, 1), vec2(-1, 0));
    vec2 g2 = ratio_gradient(1.0 - s, 1.0 - t, vec2(-1, 0), vec2(0, -1));
    vec2 g3 = ratio_gradient(1.0 - t, s, vec2(0, -1), vec2(1, 0));
    vec3 spread0 = bs[1] * bt[1] * (control_point(c, 1, 1) - c.alternates[0]);
    vec3 spread1 = bs[2] * bt[1] * (control_point(c, 2, 1) - c.alternates[1]);
    vec3 spread2 = bs[2] * bt[2] * (control_point(c, 2, 2) - c.alternates[2]);
    vec3 spread3 = bs[1] * bt[2] * (control_point(c, 1, 2) - c.alternates[3]);
    result.ds += g0.x * spread0 + g1.x * spread1 + g2.x * spread2 + g3.x * spread3;
    result.dt += g0.y * spread0 + g1.y * spread1 + g2.y * spread2 + g3.y * spread3;
  }
  return result;
}

#endif
