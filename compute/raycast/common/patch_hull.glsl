// Conservative bounds of a patch over a piece [s0, s1] x [t0, t1] of its
// domain, from its control points restricted to the piece (blossoming): a
// box, and bounds oriented by the piece's plane. Used by the dicing kernels
// for the cells' bounds and by the exact finish when it subdivides a cell.
// Needs ray.glsl and patch_eval.glsl.
#ifndef FACET_RAYCAST_PATCH_HULL_GLSL
#define FACET_RAYCAST_PATCH_HULL_GLSL

#include "rules/language.glsl"
#include "rules/surface/piece_slope.h"

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

struct Box {
  vec3 lo;
  vec3 hi;
};

// Adding the anchor rounds by less than the root tolerance every box and
// range of a hull is grown by.
Box hull_box(Hull hull) {
  return Box(hull.lo.anchor + vec3(min_entry(hull.lo.x), min_entry(hull.lo.y), min_entry(hull.lo.z)),
             hull.lo.anchor + vec3(max_entry(hull.hi.x), max_entry(hull.hi.y), max_entry(hull.hi.z)));
}

// Relative to the anchor: only differences of corners are taken.
vec3 hull_corner(Hull hull, int i, int j) {
  return 0.5 * vec3(hull.lo.x[i][j] + hull.hi.x[i][j], hull.lo.y[i][j] + hull.hi.y[i][j],
                    hull.lo.z[i][j] + hull.hi.z[i][j]);
}

// The range of a.p over the hull's control boxes, relative to the anchor
// (a box's extent along a is |a|.halfExtent).
vec2 hull_range(Hull hull, vec3 a) {
  vec2 range = vec2(INFINITE_DISTANCE, -INFINITE_DISTANCE);
  for (int i = 0; i < 4; ++i) {
    vec4 centre = 0.5 * (a.x * (hull.lo.x[i] + hull.hi.x[i]) + a.y * (hull.lo.y[i] + hull.hi.y[i]) +
                         a.z * (hull.lo.z[i] + hull.hi.z[i]));
    vec4 spread = 0.5 * (abs(a.x) * (hull.hi.x[i] - hull.lo.x[i]) + abs(a.y) * (hull.hi.y[i] - hull.lo.y[i]) +
                         abs(a.z) * (hull.hi.z[i] - hull.lo.z[i]));
    vec4 low = centre - spread, high = centre + spread;
    range = vec2(min(range.x, min(min(low.x, low.y), min(low.z, low.w))),
                 max(range.y, max(max(high.x, high.y), max(high.z, high.w))));
  }
  return range;
}

// A piece's bounds in the frame of the plane of its corners: n its normal,
// u along s, v = n x u (the axes where the corners span no plane), with the
// ranges of the hull along each, grown by `growth`. `steepness` bounds the
// slope of the surface over the piece to that plane
// (rules/surface/piece_slope.h): a ray steeper than that crosses the piece's
// surface at most once.
struct OrientedBounds {
  vec3 n;
  vec3 u;
  vec2 nRange;
  vec2 uRange;
  vec2 vRange;
  float steepness;
};

OrientedBounds oriented_bounds(Hull hull, float growth) {
  vec3 c00 = hull_corner(hull, 0, 0), c30 = hull_corner(hull, 3, 0);
  vec3 c03 = hull_corner(hull, 0, 3), c33 = hull_corner(hull, 3, 3);
  OrientedBounds b;
  bool planar = corner_plane(c00, c30, c03, c33, b.n, b.u);
  vec3 v = cross(b.n, b.u);
  b.nRange = hull_range(hull, b.n);
  b.uRange = hull_range(hull, b.u);
  b.vRange = hull_range(hull, v);
  // The slope from the ranges about the anchor, before the anchor's
  // distance from the eye enters them.
  float width = min(b.uRange.y - b.uRange.x, b.vRange.y - b.vRange.x);
  b.steepness = planar ? piece_slope_bound(b.nRange.y - b.nRange.x, width) : INFINITE_DISTANCE;
  // Adding the anchor rounds by less than the growth, at least the root
  // tolerance.
  vec3 anchor = hull.lo.anchor;
  b.nRange += dot(b.n, anchor) + vec2(-growth, growth);
  b.uRange += dot(b.u, anchor) + vec2(-growth, growth);
  b.vRange += dot(v, anchor) + vec2(-growth, growth);
  return b;
}

float extent(OrientedBounds b) {
  return length(vec3(b.uRange.y - b.uRange.x, b.vRange.y - b.vRange.x, b.nRange.y - b.nRange.x));
}

// Whether the ray meets the bounds within [tMin, tMax]; `steep`, whether
// its slope to their plane exceeds their steepness; `across`, where it
// crosses the plane halfway through the bounds, and `entry`, where it enters
// them, as fractions of their u and v ranges (starts for Newton: u runs
// along s, v along t).
bool ray_meets_bounds(Ray ray, OrientedBounds b, float tMax, out bool steep, out vec2 across, out vec2 entry) {
  vec3 v = cross(b.n, b.u);
  Ray local = Ray(vec3(dot(b.u, ray.origin), dot(v, ray.origin), dot(b.n, ray.origin)),
                  vec3(dot(b.u, ray.direction), dot(v, ray.direction), dot(b.n, ray.direction)), ray.tMin, ray.tMax);
  vec2 interval = box_interval(local, safe_inverse(local.direction), vec3(b.uRange.x, b.vRange.x, b.nRange.x),
                               vec3(b.uRange.y, b.vRange.y, b.nRange.y), tMax);
  steep = steeper_than(ray.direction, b.n, b.steepness);
  vec2 lo = vec2(b.uRange.x, b.vRange.x), size = vec2(b.uRange.y - b.uRange.x, b.vRange.y - b.vRange.x);
  float t = (0.5 * (b.nRange.x + b.nRange.y) - local.origin.z) / local.direction.z;
  across = clamp((local.origin.xy + t * local.direction.xy - lo) / size, 0.0, 1.0);
  if (!(abs(local.direction.z) > 0.0)) across = vec2(0.5);
  entry = clamp((local.origin.xy + interval.x * local.direction.xy - lo) / size, 0.0, 1.0);
  return interval.x <= interval.y;
}

#endif
