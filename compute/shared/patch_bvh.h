// The patch BVH as the GPU reads it: element types of the flat arrays that
// facet::scene::PatchBvh builds on the CPU and uploads unchanged.
//
// One file, two languages. It is valid GLSL (std430 and scalar block layouts
// agree for it) and valid C++:
//   - only 32-bit scalars (float, uint) as members, no vectors, no arrays, so
//     every member is 4-byte aligned and no layout rule can insert padding;
//   - constants are `const uint` at file scope;
//   - no #include, no C++-only syntax.
// GLSL:  #extension GL_GOOGLE_include_directive : require
//        #include "compute/shared/patch_bvh.h"      (compiled with -I<repo root>)
// C++:   include scenes/gpu_layout.h, which includes this file inside
//        namespace facet::gpu_layout after `using uint = std::uint32_t;` and
//        static_asserts every size below.
#ifndef FACET_SHARED_PATCH_BVH_H
#define FACET_SHARED_PATCH_BVH_H

// A BVH node, 32 bytes. Nodes are stored depth-first: an interior node's
// first child is the next node, its second child is at `next`.
// Leaf (patchCount > 0): patches first .. first + patchCount - 1 of the
// PatchRecord array; `next` then holds that first index.
// Bounds are rounded outwards from the double-precision hull, so they are
// conservative in float too.
struct PatchBvhNode {
  float minX;
  float minY;
  float minZ;
  uint next;
  float maxX;
  float maxY;
  float maxZ;
  uint patchCount;
};

// Kinds of patch: both are stored as 16 bicubic Bézier points; a Gregory
// patch adds 4 alternate interior points blended rationally (formulas in
// scenes/bezier_patch.h).
const uint FACET_PATCH_BEZIER = 0u;
const uint FACET_PATCH_GREGORY = 1u;
const uint FACET_PATCH_POINTS_BEZIER = 16u;
const uint FACET_PATCH_POINTS_GREGORY = 20u;

// One limit-surface patch, 48 bytes, in BVH leaf order.
// Patch-local (s, t) in [0,1]^2 is face parameter
// (u, v) = (faceU0 + s * faceSize, faceV0 + t * faceSize) on ptex face
// `ptexFace`; hits report face, (u, v) and `sourcePatch`.
struct PatchRecord {
  uint kind;        // FACET_PATCH_BEZIER or FACET_PATCH_GREGORY
  uint firstPoint;  // index of its first PatchPoint
  uint ptexFace;
  uint coarseFace;  // the cage face the ptex face belongs to
  float faceU0;
  float faceV0;
  float faceSize;       // a power of two: exact in float
  uint sourcePatch;     // OpenSubdiv patch index: the patch id in hits and AOVs
  uint boundaryMask;    // OpenSubdiv edge bits (1 v=0, 2 u=1, 4 v=1, 8 u=0), already folded into the points
  uint depth;           // refinement level of the patch
  uint pointCount;      // FACET_PATCH_POINTS_BEZIER or FACET_PATCH_POINTS_GREGORY
  uint transitionMask;  // same edge bits: the neighbour across is one level
                        // deeper, so crack-free dicing splits that edge twice as finely
};

// A control point, 12 bytes. Points of patch p: 16 Bézier points row-major
// (index 4*j + i, i along s), then for Gregory patches the 4 alternates of
// slots 5, 6, 10, 9.
struct PatchPoint {
  float x;
  float y;
  float z;
};

#endif
