#version 460
#extension GL_GOOGLE_include_directive : require
// surface_texcoord at one (patch, s, t) per invocation: uv, d(uv)/ds, d(uv)/dt.
layout(local_size_x = 64) in;

#include "compute/layout/patch_records.h"

layout(binding = 3) uniform samplerBuffer patchPoints;  // patch_eval.glsl's, unread here
#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/common/texcoord.glsl"

struct TexcoordCase {
  uint firstTexcoord;
  float s;
  float t;
  uint pad;
};
layout(std430, binding = 0) readonly buffer Cases { TexcoordCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec2 results[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  SurfaceTexcoord texcoord = surface_texcoord(cases[i].firstTexcoord, cases[i].s, cases[i].t);
  results[3u * i] = texcoord.uv;
  results[3u * i + 1u] = texcoord.ds;
  results[3u * i + 2u] = texcoord.dt;
}
