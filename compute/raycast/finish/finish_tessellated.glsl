// The tessellated finish: the ray against a cell's micro-triangles. A cell
// is two triangles, or where a side lies on a split patch edge, a fan
// around the mean of its corners through its boundary, split edges'
// midpoints included (the CPU reference triangulates alike). The including
// kernel declares the texel buffers gridVertices and edgeMidpoints. Needs
// ray.glsl, triangle.glsl, micro_grid.glsl.
#ifndef FACET_RAYCAST_FINISH_TESSELLATED_GLSL
#define FACET_RAYCAST_FINISH_TESSELLATED_GLSL

vec3 grid_vertex(Cell cell, uint di, uint dj) {
  return texelFetch(gridVertices, int(grid_vertex_index(cell.firstGridVertex, cell.rate, cell.i + di, cell.j + dj))).xyz;
}

vec3 edge_midpoint(Cell cell, uint edge, uint i) {
  return texelFetch(edgeMidpoints, int(edge_midpoint_index(cell.firstEdgeMidpoint, cell.rate, edge, i))).xyz;
}

void finish_tessellated(Ray ray, Cell cell, inout Hit best) {
  uint i = cell.i, j = cell.j, k = cell.rate;
  float rate = float(k);
  vec3 c00 = grid_vertex(cell, 0u, 0u), c10 = grid_vertex(cell, 1u, 0u);
  vec3 c11 = grid_vertex(cell, 1u, 1u), c01 = grid_vertex(cell, 0u, 1u);
  uint splitEdges = split_cell_edges(i, j, k, cell.transitionMask);
  vec2 s00 = vec2(i, j), s10 = vec2(i + 1u, j), s11 = vec2(i + 1u, j + 1u), s01 = vec2(i, j + 1u);
  RayShear shear = ray_shear(ray.direction);
  if (splitEdges == 0u) {
    intersect_triangle(ray, shear, c00, c10, c11, s00, s10, s11, rate, cell.patchIndex, cell.object, best);
    intersect_triangle(ray, shear, c00, c11, c01, s00, s11, s01, rate, cell.patchIndex, cell.object, best);
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
      vec3 middle = edge_midpoint(cell, edge, segment[edge]);
      vec2 middleStep = edge_midpoint_step(edge, segment[edge], k);
      intersect_triangle(ray, shear, centre, corners[edge], middle, centreStep, steps[edge], middleStep, rate,
                         cell.patchIndex, cell.object, best);
      intersect_triangle(ray, shear, centre, middle, next, centreStep, middleStep, nextStep, rate, cell.patchIndex,
                         cell.object, best);
    } else {
      intersect_triangle(ray, shear, centre, corners[edge], next, centreStep, steps[edge], nextStep, rate, cell.patchIndex,
                         cell.object, best);
    }
  }
}

#endif
