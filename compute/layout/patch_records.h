// The limit patches as the GPU reads them. C++ includes this file through
// engine/gpu_backend/raycast_layout.h; the rules of raycast_layout.h apply.
#ifndef FACET_LAYOUT_PATCH_RECORDS_H
#define FACET_LAYOUT_PATCH_RECORDS_H

// Kinds of patch: both are stored as 16 bicubic Bézier points; a Gregory
// patch adds 4 alternate interior points blended rationally (formulas in
// scenes/bezier_patch.h).
const uint FACET_PATCH_BEZIER = 0u;
const uint FACET_PATCH_GREGORY = 1u;
const uint FACET_PATCH_POINTS_BEZIER = 16u;
const uint FACET_PATCH_POINTS_GREGORY = 20u;

// One limit-surface patch, 56 bytes, in the order of its object's patch
// BVH leaves. Patch-local (s, t) in [0,1]^2 is face parameter
// (u, v) = (faceU0 + s * faceSize, faceV0 + t * faceSize) on ptex face
// `ptexFace`; hits report face, (u, v) and `sourcePatch`.
// Its points are texels firstPoint ... firstPoint + pointCount - 1 of the
// patch point texel buffer: 16 Bézier points row-major (index 4*j + i, i
// along s), then for Gregory patches the alternates of slots 5, 6, 10, 9.
struct PatchRecord {
  uint kind;        // FACET_PATCH_BEZIER or FACET_PATCH_GREGORY
  uint firstPoint;  // absolute texel index
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
  uint firstNormal;     // a mesh as authored with normals: 4 texels of authored normals, else FACET_NO_NORMALS
  uint firstTexcoord;   // a cage with texture coordinates: its first texcoord texel, else FACET_NO_TEXCOORDS
};

const uint FACET_NO_NORMALS = 0xFFFFFFFFu;

// A patch's texture coordinates, FACET_TEXCOORD_TEXELS vec4 texels of the
// texcoord texel buffer from firstTexcoord, two (u, v) points per texel:
// the 16 Bézier points in patchPoints' order, then the alternates of slots
// 5, 6, 10, 9, which repeat those slots on a polynomial patch, so that every
// texcoord patch evaluates as a Gregory patch (compute/raycast/shading/texcoord.glsl).
const uint FACET_TEXCOORD_TEXELS = 10u;
const uint FACET_NO_TEXCOORDS = 0xFFFFFFFFu;

// What the ray caster needs of a patch, FACET_HEADER_TEXELS uvec4 texels of
// the patch header texel buffer (the rest of PatchRecord is read once per
// pixel, when shading). Texel 0: its points and dicing; texel 1: where its
// cells, grid vertices and edge midpoints start, and its object.
const uint FACET_HEADER_TEXELS = 2u;
const uint FACET_HEADER_FIRST_POINT = 0u;
const uint FACET_HEADER_KIND = 1u;
const uint FACET_HEADER_TRANSITION_MASK = 2u;
const uint FACET_HEADER_RATE = 3u;  // k: cells per side
const uint FACET_HEADER_FIRST_CELL = 0u;
const uint FACET_HEADER_FIRST_GRID_VERTEX = 1u;
const uint FACET_HEADER_FIRST_EDGE_MIDPOINT = 2u;
const uint FACET_HEADER_OBJECT = 3u;

#endif
