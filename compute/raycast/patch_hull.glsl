// Conservative bounds of a patch over a piece [s0, s1] x [t0, t1] of its
// domain, from its control points restricted to the piece (blossoming), and
// how far the piece is from flat. Used by the dicing kernels for the cells'
// boxes and by the exact finish when it subdivides a cell. Needs
// patch_eval.glsl.
#ifndef FACET_RAYCAST_PATCH_HULL_GLSL
#define FACET_RAYCAST_PATCH_HULL_GLSL

// Weights of a cubic's control points in its blossom at (x1, x2, x3): the
// multi-affine Bernstein polynomials, all non-negative on [0, 1].
vec4 blossom_weights(float x1, float x2, float x3) {
  float y1 = 1.0 - x1, y2 = 1.0 - x2, y3 = 1.0 - x3;
  return vec4(y1 * y2 * y3, x1 * y2 * y3 + y1 * x2 * y3 + y1 * y2 * x3, x1 * x2 * y3 + x1 * y2 * x3 + y1 * x2 * x3,
              x1 * x2 * x3);
}

// Column k: the weights of the cubic's control points over [a, b], the
// blossoms at (a,a,a), (a,a,b), (a,b,b), (b,b,b).
mat4 restriction(float a, float b) {
  return mat4(blossom_weights(a, a, a), blossom_weights(a, a, b), blossom_weights(a, b, b), blossom_weights(b, b, b));
}

// Conservative hull of the piece [s0, s1] x [t0, t1]: per control slot a box
// [lo, hi] (a Gregory interior slot spans the blends its weight takes over
// the piece; the weights are monotone, so the piece's corners bound them),
// restricted to the piece: the weights are non-negative, so lo and hi stay
// ordered and bound the piece's points.
struct Hull {
  ControlPoints lo;
  ControlPoints hi;
};

ControlPoints restrict_grid(ControlPoints c, mat4 alongS, mat4 alongT) {
  c.x = alongT * c.x * alongS;
  c.y = alongT * c.y * alongS;
  c.z = alongT * c.z * alongS;
  return c;
}

Hull restrict_patch(ControlPoints c, float s0, float s1, float t0, float t1) {
  Hull hull;
  hull.lo = c;
  hull.hi = c;
  if (c.gregory) {
    vec4 wMin = vec4(1.0), wMax = vec4(0.0);
    for (int corner = 0; corner < 4; ++corner) {
      float s = (corner & 1) == 0 ? s0 : s1, t = (corner & 2) == 0 ? t0 : t1;
      // 0/0 at the patch corner itself leaves the full range.
      bvec4 undefined = bvec4(s + t == 0.0, (1.0 - s) + t == 0.0, (1.0 - s) + (1.0 - t) == 0.0, s + (1.0 - t) == 0.0);
      vec4 w = primary_weights(s, t);
      wMin = min(wMin, mix(w, vec4(0.0), undefined));
      wMax = max(wMax, mix(w, vec4(1.0), undefined));
    }
    // Only the four interior entries differ between the two blends.
    ControlPoints a = pinned(c, wMin), b = pinned(c, wMax);
    for (int column = 0; column < 4; ++column) {
      hull.lo.x[column] = min(a.x[column], b.x[column]);
      hull.lo.y[column] = min(a.y[column], b.y[column]);
      hull.lo.z[column] = min(a.z[column], b.z[column]);
      hull.hi.x[column] = max(a.x[column], b.x[column]);
      hull.hi.y[column] = max(a.y[column], b.y[column]);
      hull.hi.z[column] = max(a.z[column], b.z[column]);
    }
  }
  mat4 alongS = restriction(s0, s1), alongT = transpose(restriction(t0, t1));
  hull.lo = restrict_grid(hull.lo, alongS, alongT);
  hull.hi = c.gregory ? restrict_grid(hull.hi, alongS, alongT) : hull.lo;
  return hull;
}

float min_entry(mat4 m) {
  vec4 v = min(min(m[0], m[1]), min(m[2], m[3]));
  return min(min(v.x, v.y), min(v.z, v.w));
}

float max_entry(mat4 m) {
  vec4 v = max(max(m[0], m[1]), max(m[2], m[3]));
  return max(max(v.x, v.y), max(v.z, v.w));
}

// Largest distance of a control box from the bilinear patch through the
// four corner points (scenes/bezier_patch.h's flatnessError).
float flatness_error(Hull hull) {
  mat4 mx = 0.5 * (hull.lo.x + hull.hi.x), my = 0.5 * (hull.lo.y + hull.hi.y), mz = 0.5 * (hull.lo.z + hull.hi.z);
  mat4 ex = hull.hi.x - hull.lo.x, ey = hull.hi.y - hull.lo.y, ez = hull.hi.z - hull.lo.z;
  vec3 c00 = vec3(mx[0][0], my[0][0], mz[0][0]), c30 = vec3(mx[3][0], my[3][0], mz[3][0]);
  vec3 c03 = vec3(mx[0][3], my[0][3], mz[0][3]), c33 = vec3(mx[3][3], my[3][3], mz[3][3]);
  const vec4 rows = vec4(0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0);
  vec4 error = vec4(0.0);
  for (int i = 0; i < 4; ++i) {
    float s = float(i) / 3.0;
    vec3 bottom = mix(c00, c30, s), top = mix(c03, c33, s);
    vec4 dx = mx[i] - mix(vec4(bottom.x), vec4(top.x), rows);
    vec4 dy = my[i] - mix(vec4(bottom.y), vec4(top.y), rows);
    vec4 dz = mz[i] - mix(vec4(bottom.z), vec4(top.z), rows);
    vec4 spread = 0.5 * sqrt(ex[i] * ex[i] + ey[i] * ey[i] + ez[i] * ez[i]);
    error = max(error, sqrt(dx * dx + dy * dy + dz * dz) + spread);
  }
  return max(max(error.x, error.y), max(error.z, error.w));
}

struct Box {
  vec3 lo;
  vec3 hi;
};

Box hull_box(Hull hull) {
  return Box(vec3(min_entry(hull.lo.x), min_entry(hull.lo.y), min_entry(hull.lo.z)),
             vec3(max_entry(hull.hi.x), max_entry(hull.hi.y), max_entry(hull.hi.z)));
}

// A piece within EXACT_FLATNESS of its extent from the bilinear patch
// through its corners: a ray crosses it at most once away from grazing
// angles, so one Newton run decides it.
const float EXACT_FLATNESS = 1e-3;

bool hull_is_flat(Hull hull, Box box) { return flatness_error(hull) <= EXACT_FLATNESS * length(box.hi - box.lo); }

#endif
