// A patch's face-varying channels at a hit (compute/layout/patch_records.h):
// texture coordinates evaluated at patch-local (s, t), with d(uv)/ds and
// d(uv)/dt in the same (s, t) as evaluate_patch's dP/ds, dP/dt, so that
// tangents follow from the two; and the vertex colour. The CPU reference's
// counterparts are SubdivisionSurface::evaluateTexcoord and evaluateColor
// (scenes/subdivision_surface.h). Needs patch_eval.glsl.
#ifndef FACET_RAYCAST_TEXCOORD_GLSL
#define FACET_RAYCAST_TEXCOORD_GLSL

layout(set = 0, binding = 28) uniform samplerBuffer patchTexcoords;

struct SurfaceTexcoord {
  vec2 uv;
  vec2 ds;  // d(uv)/ds
  vec2 dt;  // d(uv)/dt
};

// The first texel of `channel` (a FACET_CHANNEL_* bit) of a patch whose
// channels start at `first`, of an object with `channels`; FACET_NO_TEXCOORDS
// without it. Only the colours, last, are longer than a set of coordinates.
uint channel_texel(uint first, uint channels, uint channel) {
  if ((channels & channel) == 0u) return FACET_NO_TEXCOORDS;
  return first + FACET_TEXCOORD_TEXELS * uint(bitCount(channels & (channel - 1u)));
}

// Zero without texture coordinates (firstTexcoord == FACET_NO_TEXCOORDS).
SurfaceTexcoord surface_texcoord(uint firstTexcoord, float s, float t) {
  SurfaceTexcoord result = SurfaceTexcoord(vec2(0.0), vec2(0.0), vec2(0.0));
  if (firstTexcoord == FACET_NO_TEXCOORDS) return result;
  ControlPoints c;
  for (int k = 0; k < 8; ++k) {
    vec4 pair = texelFetch(patchTexcoords, int(firstTexcoord) + k);
    c.x[k % 2 * 2][k / 2] = pair.x;
    c.y[k % 2 * 2][k / 2] = pair.y;
    c.x[k % 2 * 2 + 1][k / 2] = pair.z;
    c.y[k % 2 * 2 + 1][k / 2] = pair.w;
  }
  c.z = mat4(0.0);
  vec4 first = texelFetch(patchTexcoords, int(firstTexcoord) + 8);
  vec4 second = texelFetch(patchTexcoords, int(firstTexcoord) + 9);
  c.alternates = mat4x3(vec3(first.xy, 0.0), vec3(first.zw, 0.0), vec3(second.xy, 0.0), vec3(second.zw, 0.0));
  c.anchor = vec3(0.0);
  c.gregory = true;
  PatchSample sample_ = evaluate_patch(c, s, t);
  result.uv = sample_.position.xy;
  result.ds = sample_.ds.xy;
  result.dt = sample_.dt.xy;
  return result;
}

// The vertex colour, white without one (firstColor == FACET_NO_TEXCOORDS).
vec3 surface_color(uint firstColor, float s, float t) {
  if (firstColor == FACET_NO_TEXCOORDS) return vec3(1.0);
  ControlPoints c;
  for (int k = 0; k < 16; ++k) {
    vec3 p = texelFetch(patchTexcoords, int(firstColor) + k).xyz;
    c.x[k % 4][k / 4] = p.x;
    c.y[k % 4][k / 4] = p.y;
    c.z[k % 4][k / 4] = p.z;
  }
  for (int k = 0; k < 4; ++k) c.alternates[k] = texelFetch(patchTexcoords, int(firstColor) + 16 + k).xyz;
  c.anchor = vec3(0.0);
  c.gregory = true;
  return evaluate_patch(c, s, t).position;
}

#endif
