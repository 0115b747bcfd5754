// The bindings of the kernels that trace rays (compute/raycast/traversal/trace.glsl),
// after the scene's (scene_bindings.glsl). The tessellated method's grid
// buffers are bound, as one-texel placeholders, for the exact method too.
// Also where the finishes learn whether a hit is one a one-sided object
// passes over (culled()).
#ifndef FACET_RAYCAST_TRACE_BINDINGS_GLSL
#define FACET_RAYCAST_TRACE_BINDINGS_GLSL

#include "compute/layout/wide_bvh.h"

layout(set = 0, binding = 1) uniform usamplerBuffer bvhNodes;
layout(set = 0, binding = 5) uniform samplerBuffer gridVertices;
layout(set = 0, binding = 6) uniform samplerBuffer edgeMidpoints;
layout(set = 0, binding = 16) uniform samplerBuffer cellBounds;
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };

#include "rules/language.glsl"
#include "rules/surface/back_face.h"

// 1 where some object is one-sided (docs/rendering.md, "One-sided surfaces"),
// so that other scenes run exactly the kernels they did.
layout(constant_id = 2) const int CULLING = 0;

// Whether `object` passes over a hit of a ray along `direction` where the
// surface's geometric normal (of any length) is `normal`.
bool culled(uint object, vec3 direction, vec3 normal) {
  return CULLING == 1 && (objects[object].flags & FACET_OBJECT_CULL_BACK_FACES) != 0u &&
         is_back_face(direction, normal);
}

#endif
