// Where the tessellated method's micro-grid lives: (k + 1)^2 limit points
// per patch, row by row, and per patch edge k limit points halfway along
// its segments, used where the neighbour across is one level deeper (its
// segments are half as long, so the edge is split to stay watertight).
// Edges are numbered 0 t=0, 1 s=1, 2 t=1, 3 s=0, as OpenSubdiv's bits.
#ifndef FACET_RAYCAST_MICRO_GRID_GLSL
#define FACET_RAYCAST_MICRO_GRID_GLSL

// A cell of a patch's micro-grid, with what the finishes need of its patch
// (compute/layout/patch_records.h). The including kernel declares
// patchHeaders.
struct Cell {
  uint patchIndex;
  uint object;
  uint i;
  uint j;
  uint rate;
  uint firstPoint;
  uint kind;
  uint transitionMask;
  uint firstCell;
  uint firstGridVertex;
  uint firstEdgeMidpoint;
};

Cell patch_cell(uint patchIndex, uint i, uint j) {
  uvec4 a = texelFetch(patchHeaders, int(patchIndex * FACET_HEADER_TEXELS));
  uvec4 b = texelFetch(patchHeaders, int(patchIndex * FACET_HEADER_TEXELS + 1u));
  return Cell(patchIndex, b[FACET_HEADER_OBJECT], i, j, a[FACET_HEADER_RATE], a[FACET_HEADER_FIRST_POINT],
              a[FACET_HEADER_KIND], a[FACET_HEADER_TRANSITION_MASK], b[FACET_HEADER_FIRST_CELL],
              b[FACET_HEADER_FIRST_GRID_VERTEX], b[FACET_HEADER_FIRST_EDGE_MIDPOINT]);
}

// The cell's domain [s0, s1] x [t0, t1] as (s0, s1, t0, t1).
vec4 cell_domain(Cell cell) {
  float size = 1.0 / float(cell.rate);
  return vec4(float(cell.i) * size, float(cell.i + 1u) * size, float(cell.j) * size, float(cell.j + 1u) * size);
}

uint grid_vertex_index(uint firstGridVertex, uint rate, uint i, uint j) { return firstGridVertex + j * (rate + 1u) + i; }

uint edge_midpoint_index(uint firstEdgeMidpoint, uint rate, uint edge, uint i) {
  return firstEdgeMidpoint + edge * rate + i;
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
