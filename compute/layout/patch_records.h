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

// What shading reads of a limit-surface patch, once per hit: 32 bytes,
// FACET_PATCH_RECORD_TEXELS uvec4 texels of the patch record texel buffer
// (floats as their bits), in the order of its object's patch BVH leaves. A
// texel buffer is bounded by maxTexelBufferElements, not by the far smaller
// maxStorageBufferBindingSize (docs/reliability.md, "Limits").
// Patch-local (s, t) in [0,1]^2 is face parameter
// (u, v) = (faceU0 + s * faceSize, faceV0 + t * faceSize) on ptex face
// `ptexFace`; hits report face, (u, v) and `sourcePatch`. The patch's kind
// and first point are in its header (below): its points are texels
// firstPoint ... firstPoint + 15 (Bézier) or + 19 (Gregory) of the patch
// point texel buffer: 16 Bézier points row-major (index 4*j + i, i along
// s), then for Gregory patches the alternates of slots 5, 6, 10, 9. The first
// point is stored relative to the eye and is the patch's anchor; every other
// point relative to the anchor. Derivatives and normals then come from
// differences taken in double on the host: a patch far smaller than its
// distance from the eye keeps them, where eye-relative floats would round
// its control points by a share of that distance (docs/rendering.md,
// "Precise anywhere").
struct PatchRecord {
  uint sourcePatch;    // OpenSubdiv patch index: the patch id in hits and AOVs
  uint coarseFace;     // the cage face the ptex face belongs to
  uint firstNormal;  // a mesh as authored with normals: 4 texels of authored normals (then FACET_OBJECT_TANGENTS), else
                     // FACET_NO_NORMALS
  uint firstTexcoord;  // a cage with face-varying channels: the first of their texels, else FACET_NO_TEXCOORDS
  float faceU0;
  float faceV0;
  float faceSize;  // a power of two: exact in float
  uint ptexFace;
};
const uint FACET_PATCH_RECORD_TEXELS = 2u;

const uint FACET_NO_NORMALS = 0xFFFFFFFFu;

// A patch's face-varying channels, those its object's ObjectRange.channels
// names, one after the other in the order of the bits below from
// firstTexcoord in the texcoord texel buffer. Each is 20 points: the 16
// Bézier points in patchPoints' order, then the alternates of slots 5, 6, 10,
// 9, which repeat those slots on a polynomial patch, so that every channel
// evaluates as a Gregory patch (compute/raycast/common/texcoord.glsl). A set
// of texture coordinates is FACET_TEXCOORD_TEXELS texels, two (u, v) points
// per texel; the vertex colours, last, FACET_COLOR_TEXELS texels, one RGB
// point per texel.
const uint FACET_TEXCOORD_TEXELS = 10u;
const uint FACET_COLOR_TEXELS = 20u;
const uint FACET_NO_TEXCOORDS = 0xFFFFFFFFu;
const uint FACET_CHANNEL_TEXCOORD0 = 1u;  // glTF TEXCOORD_0
const uint FACET_CHANNEL_TEXCOORD1 = 2u;  // glTF TEXCOORD_1
const uint FACET_CHANNEL_COLOR = 4u;      // glTF COLOR_0

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
