#version 450
// Compiles the GPU ray caster's shared headers as GLSL, in the buffer
// layouts the kernels use, so a C++-only construct in them breaks the build.
#extension GL_GOOGLE_include_directive : require
#include "compute/layout/patch_records.h"
#include "compute/layout/raycast_layout.h"
#include "compute/layout/path_layout.h"
#include "compute/layout/wide_bvh.h"

layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Patches { PatchRecord patches[]; };
layout(std430, binding = 1) readonly buffer Objects { ObjectRange objects[]; };
layout(std430, binding = 2) readonly buffer ShadowRays { ShadowRayRecord shadowRays[]; };
layout(std430, binding = 3) buffer Counters { RenderCounters counters; };
layout(std430, binding = 4) readonly buffer Hits { HitRecord hits[]; };
layout(std140, binding = 5) uniform FrameBlock { FrameParams frame; };
layout(std430, binding = 6) readonly buffer Fallbacks { FallbackRecord fallbacks[]; };
layout(std430, binding = 7) readonly buffer PathStates { PathState pathStates[]; };

// The members the test checks are read, so glslang keeps (and lays out) them.
void main() {
  PatchRecord p = patches[0];
  ObjectRange o = objects[0];
  ShadowRayRecord r = shadowRays[0];
  FallbackRecord f = fallbacks[0];
  counters.cameraFallbacks = f.ray + f.cell + uint(f.t) + f.patchIndex + uint(f.tParam) + frame.fallbackCapacity +
                             p.sourcePatch + p.coarseFace + p.firstNormal + p.firstTexcoord + uint(p.faceU0) +
                             uint(p.faceV0) + uint(p.faceSize) + p.ptexFace + o.firstPatch + frame.rootNode +
                             o.rate + o.firstQuadtreeNode + o.firstEdgeMidpoint + o.channels + uint(r.ray.tMax) + r.slot +
                             hits[0].patchIndex + frame.patchCount + uint(frame.tolerance) + frame.dfgSize + frame.compensationSize +
                             pathStates[0].transmissionTaken + uint(frame.transmissionBounces) + uint(frame.eyeSigmaB) + FACET_BVH4_TEXELS;
  counters.shadowX = 0u;
  counters.cameraFallbackX = 0u;
  counters.shadowFallbackZ = 0u;
}
