// The scene at the bindings every ray-casting kernel shares, and the index
// of the invocation over a 2D grid of 64-wide workgroups (one dimension of
// workgroups is limited to 65535).
#ifndef FACET_RAYCAST_SCENE_BINDINGS_GLSL
#define FACET_RAYCAST_SCENE_BINDINGS_GLSL

#include "compute/shared/patch_records.h"
#include "compute/shared/raycast_layout.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 2, std430) readonly buffer Patches { PatchRecord patches[]; };
layout(set = 0, binding = 3) uniform samplerBuffer patchPoints;
layout(set = 0, binding = 4, std430) readonly buffer Objects { ObjectRange objects[]; };
layout(set = 0, binding = 7) uniform usamplerBuffer patchHeaders;

uint invocation_index() { return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u; }

#endif
