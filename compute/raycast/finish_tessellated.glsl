// The tessellated finish: the ray against cell (i, j)'s micro-triangles.
// A cell is two triangles, or where a side lies on a split patch edge, a
// fan around the mean of its corners through its boundary, split edges'
// midpoints included (the CPU reference triangulates alike). The including
// kernel declares the texel buffers gridVertices, edgeMidpoints and
// patchHeaders. Needs ray.glsl, triangle.glsl, micro_grid.glsl.
#ifndef FACET_RAYCAST_FINISH_TESSELLATED_GLSL
#define FACET_RAYCAST_FINISH_TESSELLATED_GLSL

vec3 grid_vertex(uint index) { return texelFetch(gridVertices, int(index)).xyz; }

vec3 edge_midpoint(uint index) { return texelFetch(edgeMidpoints, int(index)).xyz; }

void finish_tessellated(Ray ray, ObjectRange range, uint object, uint localPatch, uint i, uint j, inout Hit best) {
  uint k = range.rate, patchIndex = range.firstPatch + localPatch;
  float rate = float(k);
  vec3 c00 = grid_vertex(grid_vertex_index(range, localPatch, i, j));
  vec3 c10 = grid_vertex(grid_vertex_index(range, localPatch, i + 1u, j));
  vec3 c11 = grid_vertex(grid_vertex_index(range, localPatch, i + 1u, j + 1u));
  vec3 c01 = grid_vertex(grid_vertex_index(range, localPatch, i, j + 1u));
  bool border = i == 0u || j == 0u || i == k - 1u || j == k - 1u;
  uint splitEdges =
      border ? split_cell_edges(i, j, k, texelFetch(patchHeaders, int(patchIndex))[FACET_HEADER_TRANSITION_MASK]) : 0u;
  vec2 s00 = vec2(i, j), s10 = vec2(i + 1u, j), s11 = vec2(i + 1u, j + 1u), s01 = vec2(i, j + 1u);
  if (splitEdges == 0u) {
    intersect_triangle(ray, c00, c10, c11, s00, s10, s11, rate, patchIndex, object, best);
    intersect_triangle(ray, c00, c11, c01, s00, s11, s01, rate, patchIndex, object, best);
    return;
  }
  vec3 corners[4] = vec3[4](c00, c10, c11, c01);
  vec2 steps[4] = vec2[4](s00, s10, s11, s01);
  vec3 centre = 0.25 * (c00 + c10 + c11 + c01);
  vec2 centreStep = vec2(float(i) + 0.5, float(j) + 0.5);
  uint segment[4] = uint[4](i, j, i, j);
  for (uint edge = 0u; edge < 4u; ++edge) {
    vec3 next = corners[(edge + 1u) % 4u];
    vec2 nextStep = steps[(edge + 1u) % 4u];
    if (((splitEdges >> edge) & 1u) != 0u) {
      vec3 middle = edge_midpoint(edge_midpoint_index(range, localPatch, edge, segment[edge]));
      vec2 middleStep = edge_midpoint_step(edge, segment[edge], k);
      intersect_triangle(ray, centre, corners[edge], middle, centreStep, steps[edge], middleStep, rate, patchIndex,
                         object, best);
      intersect_triangle(ray, centre, middle, next, centreStep, middleStep, nextStep, rate, patchIndex, object, best);
    } else {
      intersect_triangle(ray, centre, corners[edge], next, centreStep, steps[edge], nextStep, rate, patchIndex, object,
                         best);
    }
  }
}

#endif
