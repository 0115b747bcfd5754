// The exact finish: the ray against the limit surface over one cell.
// Newton runs only where the ray passes through the cell's box and slab
// (compute/shared/wide_bvh.h), which exclude it from most cells whose box it
// merely crosses. Started from the cell's centre, it finds a root: a true
// intersection wherever on the patch it lies. A root inside the cell
// settles the cell; one beyond it settles a flat cell too
// (compute/raycast/patch_hull.glsl), which the ray crosses at most once.
// Where Newton fails, or leaves a cell that is not flat, the cell's domain
// is subdivided, its pieces culled by their hulls, until pieces are flat
// (the CPU reference's method, engine/cpu/intersect.h); such fallbacks are
// counted. The including kernel declares patchHeaders, patchPoints,
// cellBounds and `counters`. Needs ray.glsl, patch_eval.glsl, patch_hull.glsl.
//
// Float, where the CPU reference works in double: Newton accepts a root
// within `frame.tolerance` of the ray, a few float ulps of the scene's
// coordinates (relative to the eye) rather than the CPU's 1e-9 x diagonal;
// the dicing kernels grow every cell's box by that tolerance.
#ifndef FACET_RAYCAST_FINISH_EXACT_GLSL
#define FACET_RAYCAST_FINISH_EXACT_GLSL

const int NEWTON_FAILED = 0;
const int NEWTON_ROOT_INSIDE = 1;   // the root lies in the piece
const int NEWTON_ROOT_OUTSIDE = 2;  // elsewhere on the patch

// Newton on (s, t, rayT) from the piece centre, the CPU's safeguards: (s, t)
// clamped to the patch, a singular system or NEWTON_STEPS steps end the run.
// From the centre of a flat piece a root converges in a handful of steps,
// so fewer than the CPU's 40 suffice. A root in [tMin, best.t) becomes the
// hit.
const int NEWTON_STEPS = 10;

int newton(ControlPoints c, Ray ray, uint patchIndex, uint object, vec4 piece, inout Hit best) {
  float dd = dot(ray.direction, ray.direction);
  float s = 0.5 * (piece.x + piece.y), t = 0.5 * (piece.z + piece.w);
  PatchSample point = evaluate_patch(c, s, t);
  float rayT = dot(point.position - ray.origin, ray.direction) / dd;
  // Past the tolerance, one more step: convergence is quadratic, so it lands
  // at float's resolution, which the depth and normal AOVs benefit from; it
  // is kept only if it did not make the residual worse.
  bool converged = false;
  float lastResidual = 0.0;
  vec3 lastSt = vec3(s, t, rayT);
  for (int iteration = 0; iteration < NEWTON_STEPS + 1; ++iteration) {
    vec3 residual = point.position - (ray.origin + rayT * ray.direction);
    float error = length(residual);
    if (converged) {
      if (error > lastResidual) {
        s = lastSt.x;
        t = lastSt.y;
        rayT = lastSt.z;
      }
      break;
    }
    if (error <= frame.tolerance) {
      converged = true;
      lastResidual = error;
      lastSt = vec3(s, t, rayT);
    }
    vec3 a = point.ds, b = point.dt, e = -ray.direction;
    float det = dot(a, cross(b, e));
    if (!(abs(det) > 1e-7 * length(a) * length(b) * length(e))) {
      if (converged) break;
      return NEWTON_FAILED;
    }
    s = clamp(s - dot(residual, cross(b, e)) / det, 0.0, 1.0);
    t = clamp(t - dot(a, cross(residual, e)) / det, 0.0, 1.0);
    point = evaluate_patch(c, s, t);
    rayT = dot(point.position - ray.origin, ray.direction) / dd;
  }
  if (!converged) return NEWTON_FAILED;
  float margin = 1e-6 * (piece.y - piece.x);
  bool inside = s >= piece.x - margin && s <= piece.y + margin && t >= piece.z - margin && t <= piece.w + margin;
  if (rayT >= ray.tMin && rayT < best.t) {
    best.t = rayT;
    best.patchIndex = patchIndex;
    best.object = object;
    best.st = vec2(s, t);
    best.geometricNormal = vec3(0.0);
  }
  return inside ? NEWTON_ROOT_INSIDE : NEWTON_ROOT_OUTSIDE;
}

const int SUBDIVISION_MAX_DEPTH = 16;
const int SUBDIVISION_STACK = 64;

// Pieces of `cell` as (depth, i, j): cell + [i, i + 1] x [j, j + 1] / 2^depth.
void subdivide_cell(ControlPoints c, Ray ray, uint patchIndex, uint object, vec4 cell, inout Hit best) {
  vec3 inverseDirection = safe_inverse(ray.direction);
  uvec3 stack[SUBDIVISION_STACK];
  int top = 0;
  stack[top++] = uvec3(0u);
  vec2 cellSize = vec2(cell.y - cell.x, cell.w - cell.z);
  while (top > 0) {
    uvec3 piece = stack[--top];
    vec2 size = cellSize / float(1u << piece.x);
    vec4 domain = vec4(cell.x + float(piece.y) * size.x, cell.x + float(piece.y + 1u) * size.x,
                       cell.z + float(piece.z) * size.y, cell.z + float(piece.z + 1u) * size.y);
    Hull hull = restrict_patch(c, domain.x, domain.y, domain.z, domain.w);
    Box box = hull_box(hull);
    // Grown by the tolerance: a root may sit that far off the hull.
    vec2 interval = box_interval(ray, inverseDirection, box.lo - frame.tolerance, box.hi + frame.tolerance, best.t);
    if (interval.x > interval.y) continue;
    bool splittable = int(piece.x) < SUBDIVISION_MAX_DEPTH && length(box.hi - box.lo) > frame.minimumPiece &&
                      top + 4 <= SUBDIVISION_STACK;
    if (hull_is_flat(hull, box) || !splittable) {
      if (newton(c, ray, patchIndex, object, domain, best) == NEWTON_ROOT_INSIDE || !splittable) continue;
    }
    uint depth = piece.x + 1u, i = 2u * piece.y, j = 2u * piece.z;
    stack[top++] = uvec3(depth, i, j);
    stack[top++] = uvec3(depth, i + 1u, j);
    stack[top++] = uvec3(depth, i, j + 1u);
    stack[top++] = uvec3(depth, i + 1u, j + 1u);
  }
}

// Whether the ray meets the cell's box and slab together within [tMin, tMax].
bool ray_meets_cell(Ray ray, uint cell, float tMax) {
  int texel = int(cell * FACET_CELL_TEXELS);
  vec4 lo = texelFetch(cellBounds, texel), hi = texelFetch(cellBounds, texel + 1);
  vec3 n = texelFetch(cellBounds, texel + 2).xyz;
  vec2 interval = box_interval(ray, safe_inverse(ray.direction), lo.xyz, hi.xyz, tMax);
  float enter = interval.x, leave = interval.y;
  float nd = dot(n, ray.direction), no = dot(n, ray.origin);
  if (nd != 0.0) {
    float s0 = (lo.w - no) / nd, s1 = (hi.w - no) / nd;
    enter = max(enter, min(s0, s1));
    leave = min(leave, max(s0, s1) * SLAB_WIDENING);
  } else if (n != vec3(0.0) && (no < lo.w || no > hi.w)) {
    return false;
  }
  return enter <= leave;
}

void finish_exact(Ray ray, ObjectRange range, uint object, uint localPatch, uint i, uint j, bool flatCell,
                  inout Hit best) {
  if (!ray_meets_cell(ray, range.firstCell + (localPatch * range.rate + j) * range.rate + i, best.t)) return;
  uint patchIndex = range.firstPatch + localPatch;
  uvec4 header = texelFetch(patchHeaders, int(patchIndex));
  ControlPoints c = load_control_points(header[FACET_HEADER_FIRST_POINT], header[FACET_HEADER_KIND]);
  float size = 1.0 / float(range.rate);
  vec4 cell = vec4(float(i) * size, float(i + 1u) * size, float(j) * size, float(j + 1u) * size);
  int newtonResult = newton(c, ray, patchIndex, object, cell, best);
  if (newtonResult == NEWTON_ROOT_INSIDE || (flatCell && newtonResult == NEWTON_ROOT_OUTSIDE)) return;
  atomicAdd(counters.newtonFallbacks, 1u);
  subdivide_cell(c, ray, patchIndex, object, cell, best);
}

#endif
