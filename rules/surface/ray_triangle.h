// A ray against a triangle, watertight over triangles that share their
// edges' end points (Woop, Benthin and Wald 2013, "Watertight Ray/Triangle
// Intersection", JCGT 2(1)). The corners are moved into the ray's frame, its
// origin at 0 and its direction sheared onto the axis where it is largest,
// and which side of an edge the ray passes is the sign of the 2D cross
// product of the edge's two ends there. That product is antisymmetric in the
// ends: the two triangles on an edge take them in opposite order and compute
// the sign exactly opposite, so no ray passes between them. (Möller and
// Trumbore's test measures each triangle's edges from its own first corner
// and leaves rounding gaps along shared edges.) A ray through an edge or a
// corner meets every triangle there; the caller keeps the nearest.
// `precise` keeps the corners' shear and the 2D cross products unfused, so
// that a corner gets the same bits in every triangle it belongs to and the
// antisymmetry holds.

#ifndef FACET_RULE_SURFACE_RAY_TRIANGLE
#define FACET_RULE_SURFACE_RAY_TRIANGLE

struct TriangleHit {
  real t;
  real wb;  // barycentric weights of the corners b and c
  real wc;
};

// The ray's frame, once per ray: `axes` are the indices of x, y and z (z
// along the ray's largest component; x and y swapped where it is negative,
// which keeps the winding), `shear` maps a point relative to the origin onto
// the plane z = 0 of that frame and scales its z to the ray's t.
struct RayShear {
  ivec3 axes;
  vec3 shear;
};

FACET_FN RayShear ray_shear(vec3 direction) {
  vec3 size = abs(direction);
  int z = size.x > size.y ? (size.x > size.z ? 0 : 2) : (size.y > size.z ? 1 : 2);
  int x = z == 2 ? 0 : z + 1, y = x == 2 ? 0 : x + 1;
  RayShear frame;
  frame.axes = direction[z] < real(0) ? ivec3(y, x, z) : ivec3(x, y, z);
  frame.shear = vec3(direction[frame.axes.x], direction[frame.axes.y], real(1)) / direction[z];
  return frame;
}

// A corner relative to the ray's origin in the ray's frame: x, y across the
// ray, z its t.
FACET_FN vec3 sheared(RayShear frame, vec3 corner) {
  real z = corner[frame.axes.z];
  FACET_PRECISE vec3 across =
      vec3(corner[frame.axes.x] - frame.shear.x * z, corner[frame.axes.y] - frame.shear.y * z, frame.shear.z * z);
  return across;
}

// The ray's side of the edge from `from` to `to`, in its frame.
FACET_FN real edge_side(vec3 from, vec3 to) {
  FACET_PRECISE real forward = from.x * to.y;
  FACET_PRECISE real backward = from.y * to.x;
  return forward - backward;
}

// False where the ray (its frame from ray_shear) misses the triangle or runs
// parallel to its plane, or the triangle has no area; t may lie anywhere on
// the ray's line.
FACET_FN bool ray_hits_triangle(RayShear frame, vec3 origin, vec3 a, vec3 b, vec3 c, FACET_OUT(TriangleHit) hit) {
  vec3 sa = sheared(frame, a - origin), sb = sheared(frame, b - origin), sc = sheared(frame, c - origin);
  real sideA = edge_side(sb, sc), sideB = edge_side(sc, sa), sideC = edge_side(sa, sb);
  bool below = sideA < real(0) || sideB < real(0) || sideC < real(0);
  bool above = sideA > real(0) || sideB > real(0) || sideC > real(0);
  real sum = sideA + sideB + sideC;
  if ((below && above) || !(abs(sum) > real(0))) return false;
  hit.t = (sideA * sa.z + sideB * sb.z + sideC * sc.z) / sum;
  hit.wb = sideB / sum;
  hit.wc = sideC / sum;
  return true;
}

#endif
