// The last level of every patch's quadtree, one invocation per node of
// 2 x 2 cells: each cell's box and reference (compute/layout/wide_bvh.h).
// Exact method: the box of the hull of the control points restricted to the
// cell, grown by the root tolerance, and the cell's oriented bounds for its
// finish (compute/layout/wide_bvh.h).
// Tessellated: the box of the cell's micro-triangles' corners.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/common/ray.glsl"
#include "compute/layout/wide_bvh.h"
#include "compute/raycast/dicing/dicing.glsl"
#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/common/patch_hull.glsl"
#include "compute/raycast/common/micro_grid.glsl"

layout(constant_id = 0) const int METHOD = 0;

layout(set = 0, binding = 1, rgba32ui) uniform writeonly uimageBuffer bvhNodesOut;
layout(set = 0, binding = 5) uniform samplerBuffer gridVertices;
layout(set = 0, binding = 6) uniform samplerBuffer edgeMidpoints;
layout(set = 0, binding = 16, rgba32f) uniform writeonly imageBuffer cellBoundsOut;

vec3 grid_point(int index) { return texelFetch(gridVertices, index).xyz; }

Box tessellated_cell_box(Cell cell) {
  Box box;
  box.lo = grid_point(int(grid_vertex_index(cell.firstGridVertex, cell.rate, cell.i, cell.j)));
  box.hi = box.lo;
  for (uint corner = 1u; corner < 4u; ++corner) {
    vec3 p = grid_point(
        int(grid_vertex_index(cell.firstGridVertex, cell.rate, cell.i + (corner & 1u), cell.j + (corner >> 1u))));
    box.lo = min(box.lo, p);
    box.hi = max(box.hi, p);
  }
  uint splitEdges = split_cell_edges(cell.i, cell.j, cell.rate, cell.transitionMask);
  uint segment[4] = uint[4](cell.i, cell.j, cell.i, cell.j);
  for (uint edge = 0u; edge < 4u; ++edge) {
    if (((splitEdges >> edge) & 1u) == 0u) continue;
    vec3 p =
        texelFetch(edgeMidpoints, int(edge_midpoint_index(cell.firstEdgeMidpoint, cell.rate, edge, segment[edge]))).xyz;
    box.lo = min(box.lo, p);
    box.hi = max(box.hi, p);
  }
  return box;
}

// The exact finish's bounds of a cell (compute/layout/wide_bvh.h), grown by
// twice the root tolerance: a root's own, and the rounding of the projections.
void store_cell_bounds(int texel, Hull hull) {
  OrientedBounds b = oriented_bounds(hull, 2.0 * frame.tolerance);
  imageStore(cellBoundsOut, texel, vec4(b.n, b.nRange.x));
  imageStore(cellBoundsOut, texel + 1, vec4(b.u, b.nRange.y));
  imageStore(cellBoundsOut, texel + 2, vec4(b.uRange, b.vRange));
  imageStore(cellBoundsOut, texel + 3, vec4(b.steepness, 0.0, 0.0, 0.0));
}

void main() {
  uint index = invocation_index();
  if (index >= frame.cellBlockCount) return;
  ObjectRange range = objects[object_of(index, RANGE_BLOCKS)];
  uint k = range.rate, level = range.quadtreeLevels - 1u, blocksPerSide = 1u << level;
  uint local = index - range.firstBlock, localPatch = local / (blocksPerSide * blocksPerSide);
  uint bx = local % blocksPerSide, by = (local / blocksPerSide) % blocksPerSide;
  uint patchIndex = range.firstPatch + localPatch;
  Cell first = patch_cell(patchIndex, 0u, 0u);
  ControlPoints c;
  if (METHOD == 0) c = load_control_points(first.firstPoint, first.kind);
  vec4 lo[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0)), hi[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  uvec4 references = uvec4(FACET_BVH4_EMPTY);
  uint node = quadtree_node(range, localPatch, level, bx, by);
  for (uint slot = 0u; slot < 4u; ++slot) {
    Cell cell = first;
    cell.i = 2u * bx + (slot & 1u);
    cell.j = 2u * by + (slot >> 1u);
    if (cell.i >= k || cell.j >= k) continue;
    Box box;
    if (METHOD == 0) {
      vec4 domain = cell_domain(cell);
      Hull hull = restrict_patch(c, domain.x, domain.y, domain.z, domain.w);
      box = hull_box(hull);
      box.lo -= frame.tolerance;
      box.hi += frame.tolerance;
      store_cell_bounds(int((cell.firstCell + cell.j * k + cell.i) * FACET_CELL_TEXELS), hull);
    } else {
      box = tessellated_cell_box(cell);
    }
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis][slot] = box.lo[axis];
      hi[axis][slot] = box.hi[axis];
    }
    references[slot] = FACET_BVH4_CELL | (node * 4u + slot);
  }
  int base = int(node * FACET_BVH4_TEXELS);
  for (int axis = 0; axis < 3; ++axis) {
    imageStore(bvhNodesOut, base + 2 * axis, floatBitsToUint(lo[axis]));
    imageStore(bvhNodesOut, base + 2 * axis + 1, floatBitsToUint(hi[axis]));
  }
  imageStore(bvhNodesOut, base + int(FACET_BVH4_REFERENCES), references);
  imageStore(bvhNodesOut, base + int(FACET_BVH4_INFO), uvec4(patchIndex, bx, by, 0u));
}
