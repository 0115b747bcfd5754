// The scene at the bindings every ray-casting kernel shares, on the
// one-invocation-per-item grid of workgroup.glsl.
#ifndef FACET_RAYCAST_SCENE_BINDINGS_GLSL
#define FACET_RAYCAST_SCENE_BINDINGS_GLSL

#include "compute/layout/patch_records.h"
#include "compute/layout/raycast_layout.h"
#include "compute/layout/path_layout.h"
#include "compute/raycast/common/workgroup.glsl"

layout(set = 0, binding = 0, std140) uniform FrameBlock { FrameParams frame; };
layout(set = 0, binding = 2) uniform usamplerBuffer patchRecords;
layout(set = 0, binding = 3) uniform samplerBuffer patchPoints;
layout(set = 0, binding = 4, std430) readonly buffer Objects { ObjectRange objects[]; };
layout(set = 0, binding = 7) uniform usamplerBuffer patchHeaders;

// PatchRecord `index` from its FACET_PATCH_RECORD_TEXELS texels.
PatchRecord load_patch_record(uint index) {
  uvec4 a = texelFetch(patchRecords, int(index * FACET_PATCH_RECORD_TEXELS));
  uvec4 b = texelFetch(patchRecords, int(index * FACET_PATCH_RECORD_TEXELS + 1u));
  return PatchRecord(a.x, a.y, a.z, a.w, uintBitsToFloat(b.x), uintBitsToFloat(b.y), uintBitsToFloat(b.z), b.w);
}

#endif
