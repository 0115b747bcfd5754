// Closest hit of each ray against the scene, by the method METHOD (0 exact,
// 1 tessellated); with `anyHit` (shadow rays) the first hit found ends the
// search. Rays with tMax < 0 are skipped.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/scene_bindings.glsl"

layout(constant_id = 0) const int METHOD = 0;

layout(set = 0, binding = 5, std430) readonly buffer GridVertices { float gridVertices[]; };
layout(set = 0, binding = 6, std430) readonly buffer EdgeMidpoints { float edgeMidpoints[]; };
layout(set = 0, binding = 7, std430) readonly buffer RowBounds { float rowBounds[]; };
layout(set = 0, binding = 8, std430) readonly buffer Rays { RayRecord rays[]; };
layout(set = 0, binding = 9, std430) writeonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 10, std140) uniform RayBatch {
  uint rayCount;
  uint anyHit;
};

#include "compute/raycast/trace.glsl"

void main() {
  uint index = invocation_index();
  if (index >= rayCount) return;
  RayRecord record = rays[index];
  Hit hit;
  hit.patchIndex = FACET_NO_HIT;
  hit.t = 0.0;
  hit.object = 0u;
  hit.st = vec2(0.0);
  hit.geometricNormal = vec3(0.0);
  if (record.tMax >= 0.0) {
    Ray ray;
    ray.origin = vec3(record.originX, record.originY, record.originZ);
    ray.direction = vec3(record.directionX, record.directionY, record.directionZ);
    ray.tMin = record.tMin;
    ray.tMax = record.tMax;
    hit = trace(ray);
  }
  hits[index] = HitRecord(hit.t, hit.patchIndex, hit.object, hit.st.x, hit.st.y, hit.geometricNormal.x,
                          hit.geometricNormal.y, hit.geometricNormal.z);
}
