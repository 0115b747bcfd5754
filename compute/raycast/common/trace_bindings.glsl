// The bindings of the kernels that trace rays (compute/raycast/traversal/trace.glsl),
// after the scene's (scene_bindings.glsl). The tessellated method's grid
// buffers are bound, as one-texel placeholders, for the exact method too.
// Also where the finishes learn which hits a ray passes over
// (hit_filter.glsl).
#ifndef FACET_RAYCAST_TRACE_BINDINGS_GLSL
#define FACET_RAYCAST_TRACE_BINDINGS_GLSL

#include "compute/layout/wide_bvh.h"

layout(set = 0, binding = 1) uniform usamplerBuffer bvhNodes;
layout(set = 0, binding = 5) uniform samplerBuffer gridVertices;
layout(set = 0, binding = 6) uniform samplerBuffer edgeMidpoints;
layout(set = 0, binding = 16) uniform samplerBuffer cellBounds;
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };

#include "compute/raycast/common/hit_filter.glsl"

#endif
