// Tessellated method: the micro-grid's limit points (compute/raycast/common/micro_grid.glsl),
// one invocation each, grid vertices first, then edge midpoints.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/dicing/dicing.glsl"
#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/common/micro_grid.glsl"

layout(set = 0, binding = 5, rgba32f) uniform writeonly imageBuffer gridVerticesOut;
layout(set = 0, binding = 6, rgba32f) uniform writeonly imageBuffer edgeMidpointsOut;

vec3 limit_point(Cell owner, vec2 st) {
  return evaluate_patch(load_control_points(owner.firstPoint, owner.kind), st.x, st.y).position;
}

void main() {
  uint index = invocation_index();
  if (index < frame.gridVertexCount) {
    ObjectRange range = objects[object_of(index, RANGE_GRID_VERTICES)];
    uint side = range.rate + 1u, local = index - range.firstGridVertex;
    uint localPatch = local / (side * side), i = local % side, j = (local / side) % side;
    vec3 p = limit_point(patch_cell(range.firstPatch + localPatch, 0u, 0u), vec2(i, j) / float(range.rate));
    imageStore(gridVerticesOut, int(index), vec4(p, 0.0));
    return;
  }
  index -= frame.gridVertexCount;
  if (index >= frame.edgeMidpointCount) return;
  ObjectRange range = objects[object_of(index, RANGE_EDGE_MIDPOINTS)];
  uint k = range.rate, local = index - range.firstEdgeMidpoint;
  uint localPatch = local / (4u * k), edge = (local / k) % 4u, i = local % k;
  Cell owner = patch_cell(range.firstPatch + localPatch, 0u, 0u);
  if (((owner.transitionMask >> edge) & 1u) == 0u) return;
  vec3 p = limit_point(owner, edge_midpoint_step(edge, i, k) / float(k));
  imageStore(edgeMidpointsOut, int(index), vec4(p, 0.0));
}
