// A ray and the closest hit found along it so far, as the finishes, the
// traversal and the kernels pass them on.
#ifndef FACET_RAYCAST_RAY_GLSL
#define FACET_RAYCAST_RAY_GLSL

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
  vec3 geometricNormal;  // tessellated: the micro-triangle's; exact: 0 (the limit normal is found when shading)
};

Ray to_ray(RayRecord r) {
  return Ray(vec3(r.originX, r.originY, r.originZ), vec3(r.directionX, r.directionY, r.directionZ), r.tMin, r.tMax);
}

Hit no_hit(float tMax) { return Hit(tMax, FACET_NO_HIT, 0u, vec2(0.0), vec3(0.0)); }

// +inf (glslang folds 1.0 / 0.0 to it).
const float INFINITE_DISTANCE = 1.0 / 0.0;

// Rounding of the slab distances can lose a hit exactly on a box face: the
// far distance is widened by a few ulps (Ize, "Robust BVH Ray Traversal",
// JCGT 2013).
const float SLAB_WIDENING = 1.0 + 4.0 * 1.1920929e-7;

// A direction component of 0 becomes a tiny one of the same sign, so that
// the slab distances stay free of NaN (0 * inf) and keep their order.
vec3 safe_inverse(vec3 direction) {
  const float tiny = 1e-30;
  vec3 magnitude = max(abs(direction), vec3(tiny));
  return 1.0 / mix(magnitude, -magnitude, lessThan(direction, vec3(0.0)));
}

// Where the ray enters and leaves the box [lo, hi] within [tMin, tMax]; it
// meets the box when enter <= leave.
vec2 box_interval(Ray ray, vec3 inverseDirection, vec3 lo, vec3 hi, float tMax) {
  vec3 t0 = (lo - ray.origin) * inverseDirection, t1 = (hi - ray.origin) * inverseDirection;
  vec3 near = min(t0, t1), far = max(t0, t1);
  return vec2(max(max(ray.tMin, near.x), max(near.y, near.z)),
              min(min(tMax, far.x), min(far.y, far.z)) * SLAB_WIDENING);
}

#endif
