// Newton's method on the ray against a patch, and what its answer decides
// for a piece of the patch's domain: the exact method's one root finder,
// for cells (finish_exact.glsl) and the pieces of the fallback
// (subdivide_cell.glsl). Needs ray.glsl, patch_eval.glsl and trace_bindings.glsl.
//
// Float, where the CPU reference works in double: Newton accepts a root
// within `frame.tolerance` of the ray, a few float ulps of the scene's
// coordinates (relative to the eye) rather than the CPU's 1e-9 x diagonal;
// the dicing kernels grow every cell's bounds by that tolerance.
#ifndef FACET_RAYCAST_EXACT_NEWTON_GLSL
#define FACET_RAYCAST_EXACT_NEWTON_GLSL

const int NEWTON_FAILED = 0;
const int NEWTON_ROOT_INSIDE = 1;   // the root lies in the piece
const int NEWTON_ROOT_OUTSIDE = 2;  // elsewhere on the patch

// Newton on (s, t, rayT) from `start` (fractions of the piece, where the ray
// crosses the piece's plane), the CPU's safeguards: a
// singular system or NEWTON_STEPS steps end the run. From the centre of a
// flat piece a root converges in a handful of steps, so fewer than the
// CPU's 40 suffice. (s, t) may leave the patch by NEWTON_OVERSHOOT, where
// the patch's polynomial goes on: a ray that meets a neighbouring patch
// then converges there instead of stalling on the edge, and the root,
// though not a hit, tells a steep ray that this cell holds none. A root on
// the patch in [tMin, best.t) becomes the hit, unless the object passes
// over it (hit_filter.glsl; the normal is ds x dt); a root passed over still
// settles its piece, as the CPU's does.
const int NEWTON_STEPS = 10;
const float NEWTON_OVERSHOOT = 0.5;

int newton(ControlPoints c, Ray ray, uint patchIndex, uint object, vec4 piece, vec2 start, inout Hit best) {
  float dd = dot(ray.direction, ray.direction);
  float s = mix(piece.x, piece.y, start.x), t = mix(piece.z, piece.w, start.y);
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
    s = clamp(s - dot(residual, cross(b, e)) / det, -NEWTON_OVERSHOOT, 1.0 + NEWTON_OVERSHOOT);
    t = clamp(t - dot(a, cross(residual, e)) / det, -NEWTON_OVERSHOOT, 1.0 + NEWTON_OVERSHOOT);
    point = evaluate_patch(c, s, t);
    rayT = dot(point.position - ray.origin, ray.direction) / dd;
  }
  if (!converged) return NEWTON_FAILED;
  float margin = 1e-6 * (piece.y - piece.x);
  bool inside = s >= piece.x - margin && s <= piece.y + margin && t >= piece.z - margin && t <= piece.w + margin;
  // On the patch is within the tolerance of it in space along each
  // parameter (to first order), as the CPU's Newton, clamped to the patch,
  // accepts a root: float may put a ray along an edge two patches share just
  // past the edge of each. Each parameter on its own, so that a fold of the
  // polynomial beyond the patch cannot bring a far root back.
  vec2 st = clamp(vec2(s, t), 0.0, 1.0);
  bool onPatch = abs(s - st.x) * length(point.ds) <= frame.tolerance &&
                 abs(t - st.y) * length(point.dt) <= frame.tolerance;
  if (onPatch && rayT >= ray.tMin && rayT < best.t &&
      !passes_over(object, ray.direction, cross(point.ds, point.dt), patchIndex, st, rayT)) {
    best.t = rayT;
    best.patchIndex = patchIndex;
    best.object = object;
    best.st = st;
    best.geometricNormal = vec3(0.0);
  }
  return inside ? NEWTON_ROOT_INSIDE : NEWTON_ROOT_OUTSIDE;
}

// Newton's verdict on a piece the ray meets: a root inside settles it; a
// root beyond it settles it for a ray steeper than its surface.
bool settled(int newtonResult, bool steep) {
  return newtonResult == NEWTON_ROOT_INSIDE || (steep && newtonResult == NEWTON_ROOT_OUTSIDE);
}

#endif
