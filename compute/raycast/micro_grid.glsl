// Where the tessellated method's micro-grid lives: (k + 1)^2 limit points
// per patch, row by row, and per patch edge k limit points halfway along
// its segments, used where the neighbour across is one level deeper (its
// segments are half as long, so the edge is split to stay watertight).
// Edges are numbered 0 t=0, 1 s=1, 2 t=1, 3 s=0, as OpenSubdiv's bits.
#ifndef FACET_RAYCAST_MICRO_GRID_GLSL
#define FACET_RAYCAST_MICRO_GRID_GLSL

uint grid_vertex_index(ObjectRange range, uint localPatch, uint i, uint j) {
  uint side = range.rate + 1u;
  return range.firstGridVertex + (localPatch * side + j) * side + i;
}

uint edge_midpoint_index(ObjectRange range, uint localPatch, uint edge, uint i) {
  return range.firstEdgeMidpoint + (localPatch * 4u + edge) * range.rate + i;
}

// The grid step (in units of 1/k) of midpoint i of `edge`.
vec2 edge_midpoint_step(uint edge, uint i, uint rate) {
  float halfStep = float(i) + 0.5, k = float(rate);
  return edge == 0u ? vec2(halfStep, 0.0) : edge == 1u ? vec2(k, halfStep) : edge == 2u ? vec2(halfStep, k)
                                                                                        : vec2(0.0, halfStep);
}

// Edge bits of cell (i, j)'s sides that lie on the patch's split edges.
uint split_cell_edges(uint i, uint j, uint k, uint transitionMask) {
  uint onEdge = (j == 0u ? 1u : 0u) | (i == k - 1u ? 2u : 0u) | (j == k - 1u ? 4u : 0u) | (i == 0u ? 8u : 0u);
  return onEdge & transitionMask;
}

#endif
