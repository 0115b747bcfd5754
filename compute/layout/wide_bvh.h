// The 4-wide BVH the ray caster traverses, shared by C++ and GLSL (the rules
// of raycast_layout.h). One node is FACET_BVH4_TEXELS uvec4 texels of a
// texel buffer: texels 0-5 hold lo.x, hi.x, lo.y, hi.y, lo.z, hi.z of its
// four children (float bits, one child per component), texel 6 their
// references, texel 7 what a node of cells holds (FACET_BVH4_INFO).
// Structure of arrays, so one slab test covers four boxes.
//
// The top levels come from the CPU: per object its patch BVH collapsed to
// four wide, and over the objects a few nodes of their own. Each patch's
// child is the root of its quadtree over a k x k micro-grid of cells, which
// the dicing kernels build on the GPU. Every box encloses what lies below
// it: the exact limit surface (from the hull of the restricted control
// points, grown by the root tolerance) or the micro-triangles.
#ifndef FACET_LAYOUT_WIDE_BVH_H
#define FACET_LAYOUT_WIDE_BVH_H

const uint FACET_BVH4_TEXELS = 8u;
const uint FACET_BVH4_REFERENCES = 6u;  // the texel of child references
// A node of 2 x 2 cells (a quadtree's last level): (patch, x, y, 0), its
// cells (2x + (slot & 1), 2y + (slot >> 1)) of the patch's micro-grid.
const uint FACET_BVH4_INFO = 7u;

// A child reference is a node index, or a cell: FACET_BVH4_CELL | node * 4 +
// slot, the node one of 2 x 2 cells.
const uint FACET_BVH4_EMPTY = 0xFFFFFFFFu;
const uint FACET_BVH4_CELL = 0x80000000u;

// The exact method's bounds of one cell, FACET_CELL_TEXELS vec4 texels of
// the cell bounds texel buffer: (n, nMin), (u, nMax), (uMin, uMax, vMin,
// vMax), (steepness, 0, 0, 0). The limit surface over the cell lies in the
// box oriented by the plane of its corners: n its normal, u along the cell's
// s direction, v = n x u, with the ranges of the hull of its restricted
// control points, grown by the root tolerance. A ray whose slope to that
// plane exceeds `steepness` (a bound on the surface's own slope over the
// cell) crosses the cell's surface at most once.
const uint FACET_CELL_TEXELS = 4u;

// Longest path of nodes from the root to a cell: the private traversal
// stack holds at most 3 per level below the root. The top levels are built
// within it (engine/gpu_backend/top_levels.h), and 17 holds every scene whose
// nodes a cell reference addresses (docs/rendering.md, "The depth of the top
// levels").
const uint FACET_BVH4_MAX_DEPTH = 17u;

#endif
