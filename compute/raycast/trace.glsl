// Closest hit of a ray against every object's patch BVH, by the exact or the
// tessellated method (the specialization constant METHOD). The including
// kernel declares nodes[], patches[], points[], objects[], gridVertices[],
// edgeMidpoints[], rowBounds[], the uniform `frame` and `anyHit`.
//
// Float, where the CPU reference works in double: boxes are tested with a
// margin of `frame.tolerance` and Newton accepts a root within
// `frame.tolerance` of the ray, a few float ulps of the scene's coordinates
// rather than the CPU's 1e-9 x diagonal (see engine/gpu_backend/gpu_renderer.h).
#ifndef FACET_RAYCAST_TRACE_GLSL
#define FACET_RAYCAST_TRACE_GLSL

#include "compute/raycast/patch_eval.glsl"

const int METHOD_EXACT = 0;
const int METHOD_TESSELLATED = 1;

struct Ray {
  vec3 origin;
  vec3 direction;
  float tMin;
  float tMax;
};

struct Hit {
  float t;
  uint patchIndex;  // absolute PatchRecord index, FACET_NO_HIT on a miss
  uint object;
  vec2 st;
  vec3 geometricNormal;
};

// Slab test against [lo, hi], restricted to [tMin, tMax], branch-free: an
// axis the ray runs parallel to keeps all t when the origin lies within the
// slab and none otherwise. Returns where the ray enters the box, or +inf
// when it misses.
float box_entry(Ray ray, vec3 lo, vec3 hi, float tMin, float tMax) {
  vec3 t0 = (lo - ray.origin) / ray.direction, t1 = (hi - ray.origin) / ray.direction;
  bvec3 parallel = equal(ray.direction, vec3(0.0));
  bvec3 outside = bvec3(uvec3(lessThan(ray.origin, lo)) | uvec3(greaterThan(ray.origin, hi)));
  vec3 infinite = vec3(uintBitsToFloat(0x7f800000u));
  vec3 enter = mix(min(t0, t1), mix(-infinite, infinite, outside), parallel);
  vec3 leave = mix(max(t0, t1), mix(infinite, -infinite, outside), parallel);
  float first = max(max(tMin, enter.x), max(enter.y, enter.z));
  float last = min(min(tMax, leave.x), min(leave.y, leave.z));
  return first <= last ? first : infinite.x;
}

bool ray_hits_box(Ray ray, vec3 lo, vec3 hi, float tMin, float tMax) {
  return box_entry(ray, lo, hi, tMin, tMax) != uintBitsToFloat(0x7f800000u);
}

// ---- exact: subdivide the patch domain, then Newton --------------------------

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

// Newton on (s, t, rayT) from the piece centre, the CPU's safeguards: (s, t)
// clamped to the patch, a singular system or NEWTON_STEPS steps end the run.
// From the centre of a flat piece a root converges in a handful of steps,
// so fewer than the CPU's 40 suffice; a run that would need more fails and
// the piece is split, which is cheaper than iterating on for the many
// pieces whose box the ray hits but whose surface it misses. A root in
// [tMin, best.t) becomes the hit; true when the root lies in the piece,
// which then needs no further splitting.
const int NEWTON_STEPS = 10;

bool newton(ControlPoints c, Ray ray, uint patchIndex, uint object, vec4 piece, inout Hit best) {
  float dd = dot(ray.direction, ray.direction);
  float s = 0.5 * (piece.x + piece.y), t = 0.5 * (piece.z + piece.w);
  PatchSample point = evaluate_patch(c, s, t);
  float rayT = dot(point.position - ray.origin, ray.direction) / dd;
  // Past the tolerance, one more step: convergence is quadratic, so it lands
  // at float's resolution, which the depth and normal AOVs benefit from; it
  // is kept only if it did not make the residual worse.
  int polishSteps = -1;
  float lastResidual = 0.0;
  vec3 lastSt = vec3(s, t, rayT);
  for (int iteration = 0; iteration < NEWTON_STEPS + 1; ++iteration) {
    vec3 residual = point.position - (ray.origin + rayT * ray.direction);
    float error = length(residual);
    if (polishSteps >= 0) {
      if (error > lastResidual) {
        s = lastSt.x;
        t = lastSt.y;
        rayT = lastSt.z;
      }
      break;
    }
    if (error <= frame.tolerance) {
      polishSteps = 0;
      lastResidual = error;
      lastSt = vec3(s, t, rayT);
    }
    vec3 a = point.ds, b = point.dt, e = -ray.direction;
    float det = dot(a, cross(b, e));
    if (!(abs(det) > 1e-7 * length(a) * length(b) * length(e))) {
      if (polishSteps >= 0) break;
      return false;
    }
    s = clamp(s - dot(residual, cross(b, e)) / det, 0.0, 1.0);
    t = clamp(t - dot(a, cross(residual, e)) / det, 0.0, 1.0);
    point = evaluate_patch(c, s, t);
    rayT = dot(point.position - ray.origin, ray.direction) / dd;
  }
  if (polishSteps < 0) return false;
  float margin = 1e-6 * (piece.y - piece.x);
  bool inside = s >= piece.x - margin && s <= piece.y + margin && t >= piece.z - margin && t <= piece.w + margin;
  // Unlike the CPU, a root before tMin also settles a flat piece (it has
  // one root): a shadow ray would otherwise split the piece it leaves down
  // to the smallest size.
  if (rayT < ray.tMin || rayT >= best.t) return inside;
  best.t = rayT;
  best.patchIndex = patchIndex;
  best.object = object;
  best.st = vec2(s, t);
  best.geometricNormal = vec3(0.0);
  return inside;
}

const int EXACT_MAX_DEPTH = 20;
const int EXACT_STACK = 64;
const float EXACT_FLATNESS = 1e-3;

// Pieces as (depth, i, j): [i, i + 1] x [j, j + 1] / 2^depth.
void intersect_patch_exact(Ray ray, uint patchIndex, uint object, uint firstPoint, inout Hit best) {
  ControlPoints c = load_control_points(firstPoint, patches[patchIndex]);
  uvec3 stack[EXACT_STACK];
  int top = 0;
  stack[top++] = uvec3(0u);
  while (top > 0) {
    uvec3 piece = stack[--top];
    float size = 1.0 / float(1u << piece.x);
    vec4 domain = vec4(float(piece.y) * size, float(piece.y + 1u) * size, float(piece.z) * size,
                       float(piece.z + 1u) * size);
    Hull hull = restrict_patch(c, domain.x, domain.y, domain.z, domain.w);
    vec3 lo = vec3(min_entry(hull.lo.x), min_entry(hull.lo.y), min_entry(hull.lo.z));
    vec3 hi = vec3(max_entry(hull.hi.x), max_entry(hull.hi.y), max_entry(hull.hi.z));
    // Grown by the tolerance: a root may sit that far off the hull.
    if (!ray_hits_box(ray, lo - frame.tolerance, hi + frame.tolerance, ray.tMin, best.t)) continue;
    float extent = length(hi - lo);
    bool isFlat = flatness_error(hull) <= EXACT_FLATNESS * extent;
    bool splittable = int(piece.x) < EXACT_MAX_DEPTH && extent > frame.minimumPiece && top + 4 <= EXACT_STACK;
    if (isFlat || !splittable) {
      if (newton(c, ray, patchIndex, object, domain, best) || !splittable) continue;
    }
    uint depth = piece.x + 1u, i = 2u * piece.y, j = 2u * piece.z;
    stack[top++] = uvec3(depth, i, j);
    stack[top++] = uvec3(depth, i + 1u, j);
    stack[top++] = uvec3(depth, i, j + 1u);
    stack[top++] = uvec3(depth, i + 1u, j + 1u);
  }
}

// ---- tessellated: k x k grid of limit points per patch ---------------------

vec3 grid_vertex(ObjectRange range, uint patchIndex, uint i, uint j) {
  uint side = range.rate + 1u;
  uint index = range.firstGridVertex + ((patchIndex - range.firstPatch) * side + j) * side + i;
  return vec3(gridVertices[3u * index], gridVertices[3u * index + 1u], gridVertices[3u * index + 2u]);
}

// Limit point halfway along segment i of `edge` (0 t=0, 1 s=1, 2 t=1, 3 s=0).
vec3 edge_midpoint(ObjectRange range, uint patchIndex, uint edge, uint i) {
  uint index = range.firstEdgeMidpoint + ((patchIndex - range.firstPatch) * 4u + edge) * range.rate + i;
  return vec3(edgeMidpoints[3u * index], edgeMidpoints[3u * index + 1u], edgeMidpoints[3u * index + 2u]);
}

vec2 edge_midpoint_step(uint edge, uint i, uint rate) {
  float half_step = float(i) + 0.5, k = float(rate);
  return edge == 0u ? vec2(half_step, 0.0) : edge == 1u ? vec2(k, half_step) : edge == 2u ? vec2(half_step, k)
                                                                                          : vec2(0.0, half_step);
}

// Möller-Trumbore; on a hit closer than best.t, records it with the grid
// step of the hit point.
void intersect_triangle(Ray ray, vec3 a, vec3 b, vec3 c, vec2 stepA, vec2 stepB, vec2 stepC, float rate,
                        uint patchIndex, uint object, inout Hit best) {
  vec3 e1 = b - a, e2 = c - a;
  vec3 p = cross(ray.direction, e2);
  float det = dot(e1, p);
  if (det == 0.0) return;
  float inverse = 1.0 / det;
  vec3 q = ray.origin - a;
  float wb = dot(q, p) * inverse;
  if (wb < 0.0 || wb > 1.0) return;
  vec3 r = cross(q, e1);
  float wc = dot(ray.direction, r) * inverse;
  if (wc < 0.0 || wb + wc > 1.0) return;
  float t = dot(e2, r) * inverse;
  if (t < ray.tMin || t >= best.t) return;
  best.t = t;
  best.patchIndex = patchIndex;
  best.object = object;
  best.st = ((1.0 - wb - wc) * stepA + wb * stepB + wc * stepC) / rate;
  best.geometricNormal = normalize(cross(e1, e2));
}

void intersect_patch_tessellated(Ray ray, uint patchIndex, uint object, ObjectRange range, inout Hit best) {
  uint k = range.rate, transition = patches[patchIndex].transitionMask;
  for (uint j = 0u; j < k; ++j) {
    uint row = 6u * (range.firstRow + (patchIndex - range.firstPatch) * k + j);
    vec3 lo = vec3(rowBounds[row], rowBounds[row + 1u], rowBounds[row + 2u]);
    vec3 hi = vec3(rowBounds[row + 3u], rowBounds[row + 4u], rowBounds[row + 5u]);
    if (!ray_hits_box(ray, lo, hi, ray.tMin, best.t)) continue;
    for (uint i = 0u; i < k; ++i) {
      // Edge bits of the cell's sides that lie on split patch edges.
      uint onEdge = (j == 0u ? 1u : 0u) | (i == k - 1u ? 2u : 0u) | (j == k - 1u ? 4u : 0u) | (i == 0u ? 8u : 0u);
      uint splitEdges = onEdge & transition;
      vec3 c00 = grid_vertex(range, patchIndex, i, j), c10 = grid_vertex(range, patchIndex, i + 1u, j);
      vec3 c11 = grid_vertex(range, patchIndex, i + 1u, j + 1u), c01 = grid_vertex(range, patchIndex, i, j + 1u);
      if (splitEdges == 0u) {
        intersect_triangle(ray, c00, c10, c11, vec2(i, j), vec2(i + 1u, j), vec2(i + 1u, j + 1u), float(k), patchIndex,
                           object, best);
        intersect_triangle(ray, c00, c11, c01, vec2(i, j), vec2(i + 1u, j + 1u), vec2(i, j + 1u), float(k), patchIndex,
                           object, best);
        continue;
      }
      vec3 corners[4] = vec3[4](c00, c10, c11, c01);
      vec2 steps[4] = vec2[4](vec2(i, j), vec2(i + 1u, j), vec2(i + 1u, j + 1u), vec2(i, j + 1u));
      // A fan around the mean of the corners through the cell's boundary,
      // counter-clockwise, with the midpoints of split edges.
      vec3 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
      vec2 centreStep = vec2(float(i) + 0.5, float(j) + 0.5);
      uint segment[4] = uint[4](i, j, i, j);
      for (uint edge = 0u; edge < 4u; ++edge) {
        vec3 next = corners[(edge + 1u) % 4u];
        vec2 nextStep = steps[(edge + 1u) % 4u];
        if (((splitEdges >> edge) & 1u) != 0u) {
          vec3 middle = edge_midpoint(range, patchIndex, edge, segment[edge]);
          vec2 middleStep = edge_midpoint_step(edge, segment[edge], k);
          intersect_triangle(ray, centre, corners[edge], middle, centreStep, steps[edge], middleStep, float(k),
                             patchIndex, object, best);
          intersect_triangle(ray, centre, middle, next, centreStep, middleStep, nextStep, float(k), patchIndex, object,
                             best);
        } else {
          intersect_triangle(ray, centre, corners[edge], next, centreStep, steps[edge], nextStep, float(k), patchIndex,
                             object, best);
        }
      }
    }
  }
}

// ---- the scene ----------------------------------------------------------------

// Depth-first, the stack never holds more than the tree's depth + 1 nodes.
// Kept short on purpose: lavapipe's cost for a local array indexed at run
// time grows with its length (64 entries cost 20-30% more than 24).
const int BVH_STACK = 32;

float node_entry(Ray ray, PatchBvhNode node, float tMax) {
  return box_entry(ray, vec3(node.minX, node.minY, node.minZ), vec3(node.maxX, node.maxY, node.maxZ), ray.tMin, tMax);
}

// Depth-first through each object's BVH, nearer child first; only children
// whose box the ray enters before the closest hit so far are visited.
Hit trace(Ray ray) {
  const float INFINITE = uintBitsToFloat(0x7f800000u);
  Hit best;
  best.t = ray.tMax;
  best.patchIndex = FACET_NO_HIT;
  best.object = 0u;
  best.st = vec2(0.0);
  best.geometricNormal = vec3(0.0);
  for (uint object = 0u; object < frame.objectCount; ++object) {
    ObjectRange range = objects[object];
    if (node_entry(ray, nodes[range.firstNode], best.t) == INFINITE) continue;
    uint stack[BVH_STACK];
    int top = 0;
    uint index = 0u;
    while (true) {
      PatchBvhNode node = nodes[range.firstNode + index];
      if (node.patchCount > 0u) {
        for (uint k = 0u; k < node.patchCount; ++k) {
          uint patchIndex = range.firstPatch + node.next + k;
          if (METHOD == METHOD_EXACT)
            intersect_patch_exact(ray, patchIndex, object, range.firstPoint, best);
          else
            intersect_patch_tessellated(ray, patchIndex, object, range, best);
          if (anyHit != 0u && best.patchIndex != FACET_NO_HIT) return best;
        }
      } else {
        uint first = index + 1u, second = node.next;
        float tFirst = node_entry(ray, nodes[range.firstNode + first], best.t);
        float tSecond = node_entry(ray, nodes[range.firstNode + second], best.t);
        if (tFirst != INFINITE && tSecond != INFINITE) {
          bool firstNearer = tFirst <= tSecond;
          stack[top++] = firstNearer ? second : first;
          index = firstNearer ? first : second;
          continue;
        }
        if (tFirst != INFINITE || tSecond != INFINITE) {
          index = tFirst != INFINITE ? first : second;
          continue;
        }
      }
      if (top == 0) break;
      index = stack[--top];
    }
  }
  return best;
}

#endif
