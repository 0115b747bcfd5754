#version 450
// Compiles compute/shared/patch_bvh.h as GLSL, in the buffer layouts the GPU
// path uses, so a C++-only construct in the shared header breaks the build.
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/patch_bvh.h"

layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Nodes { PatchBvhNode nodes[]; };
layout(std430, binding = 1) readonly buffer Patches { PatchRecord patches[]; };
layout(std430, binding = 2) readonly buffer Points { PatchPoint points[]; };
layout(std430, binding = 3) writeonly buffer Result { float result[]; };

// Every member is read, so glslang keeps (and lays out) all of them.
void main() {
    PatchBvhNode node = nodes[0];
    PatchRecord record = patches[node.next];
    uint last = record.firstPoint + (record.kind == FACET_PATCH_GREGORY ? FACET_PATCH_POINTS_GREGORY : FACET_PATCH_POINTS_BEZIER) - 1u;
    PatchPoint point = points[last];
    result[0] = point.x + point.y + point.z + node.minX + node.minY + node.minZ + node.maxX + node.maxY + node.maxZ +
                float(node.patchCount + record.ptexFace + record.coarseFace + record.sourcePatch + record.boundaryMask +
                      record.depth + record.pointCount + record.transitionMask) +
                record.faceU0 + record.faceV0 + record.faceSize;
}
