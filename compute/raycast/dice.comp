// Tessellated method: per patch, the (k + 1)^2 limit points of its grid, the
// limit points halfway along the segments of its transition edges (the
// neighbour across is one level deeper, so those edges are split twice as
// finely to stay watertight), and the box of each row of cells.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/scene_bindings.glsl"

layout(set = 0, binding = 5, std430) buffer GridVertices { float gridVertices[]; };
layout(set = 0, binding = 6, std430) buffer EdgeMidpoints { float edgeMidpoints[]; };
layout(set = 0, binding = 7, std430) writeonly buffer RowBounds { float rowBounds[]; };

#include "compute/raycast/patch_eval.glsl"

void store(uint index, vec3 p) {
  gridVertices[3u * index] = p.x;
  gridVertices[3u * index + 1u] = p.y;
  gridVertices[3u * index + 2u] = p.z;
}

vec3 load(uint index) {
  return vec3(gridVertices[3u * index], gridVertices[3u * index + 1u], gridVertices[3u * index + 2u]);
}

vec3 load_midpoint(uint index) {
  return vec3(edgeMidpoints[3u * index], edgeMidpoints[3u * index + 1u], edgeMidpoints[3u * index + 2u]);
}

void main() {
  uint patchIndex = invocation_index();
  if (patchIndex >= uint(patches.length())) return;
  uint object = 0u;
  for (uint o = 1u; o < frame.objectCount; ++o)
    if (objects[o].firstPatch <= patchIndex) object = o;
  ObjectRange range = objects[object];
  PatchRecord record = patches[patchIndex];
  ControlPoints c = load_control_points(range.firstPoint, record);
  uint k = range.rate, local = patchIndex - range.firstPatch;
  uint firstVertex = range.firstGridVertex + local * (k + 1u) * (k + 1u);
  for (uint j = 0u; j <= k; ++j)
    for (uint i = 0u; i <= k; ++i)
      store(firstVertex + j * (k + 1u) + i, evaluate_patch(c, float(i) / float(k), float(j) / float(k)).position);

  for (uint edge = 0u; edge < 4u; ++edge) {
    if (((record.transitionMask >> edge) & 1u) == 0u) continue;
    for (uint i = 0u; i < k; ++i) {
      float half_step = (float(i) + 0.5) / float(k);
      vec2 st = edge == 0u   ? vec2(half_step, 0.0)
                : edge == 1u ? vec2(1.0, half_step)
                : edge == 2u ? vec2(half_step, 1.0)
                             : vec2(0.0, half_step);
      vec3 p = evaluate_patch(c, st.x, st.y).position;
      uint index = range.firstEdgeMidpoint + (local * 4u + edge) * k + i;
      edgeMidpoints[3u * index] = p.x;
      edgeMidpoints[3u * index + 1u] = p.y;
      edgeMidpoints[3u * index + 2u] = p.z;
    }
  }
  for (uint j = 0u; j < k; ++j) {
    vec3 lo = load(firstVertex + j * (k + 1u)), hi = lo;
    for (uint i = 0u; i <= k; ++i) {
      vec3 a = load(firstVertex + j * (k + 1u) + i), b = load(firstVertex + (j + 1u) * (k + 1u) + i);
      lo = min(lo, min(a, b));
      hi = max(hi, max(a, b));
    }
    // Midpoints of split edges belong to the cells along them: those of the
    // s = 0 and s = 1 edges to row j, the others to the first and last rows.
    for (uint edge = 0u; edge < 4u; ++edge) {
      if (((record.transitionMask >> edge) & 1u) == 0u) continue;
      uint firstMidpoint = range.firstEdgeMidpoint + (local * 4u + edge) * k;
      bool sideEdge = edge == 1u || edge == 3u;
      if (sideEdge) {
        lo = min(lo, load_midpoint(firstMidpoint + j));
        hi = max(hi, load_midpoint(firstMidpoint + j));
      } else if ((edge == 0u && j == 0u) || (edge == 2u && j == k - 1u)) {
        for (uint i = 0u; i < k; ++i) {
          lo = min(lo, load_midpoint(firstMidpoint + i));
          hi = max(hi, load_midpoint(firstMidpoint + i));
        }
      }
    }
    uint row = 6u * (range.firstRow + local * k + j);
    rowBounds[row] = lo.x;
    rowBounds[row + 1u] = lo.y;
    rowBounds[row + 2u] = lo.z;
    rowBounds[row + 3u] = hi.x;
    rowBounds[row + 4u] = hi.y;
    rowBounds[row + 5u] = hi.z;
  }
}
