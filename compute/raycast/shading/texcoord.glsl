// Texture coordinates at a hit: the patch's face-varying patch
// (compute/layout/patch_records.h, FACET_TEXCOORD_TEXELS) evaluated at
// patch-local (s, t), with d(uv)/ds and d(uv)/dt in the same (s, t) as
// evaluate_patch's dP/ds, dP/dt, so that tangents follow from the two.
// The CPU reference's counterpart is SubdivisionSurface::evaluateTexcoord
// (scenes/subdivision_surface.h). Needs patch_eval.glsl.
#ifndef FACET_RAYCAST_TEXCOORD_GLSL
#define FACET_RAYCAST_TEXCOORD_GLSL

layout(set = 0, binding = 28) uniform samplerBuffer patchTexcoords;

struct SurfaceTexcoord {
  vec2 uv;
  vec2 ds;  // d(uv)/ds
  vec2 dt;  // d(uv)/dt
};

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
  c.gregory = true;
  PatchSample sample_ = evaluate_patch(c, s, t);
  result.uv = sample_.position.xy;
  result.ds = sample_.ds.xy;
  result.dt = sample_.dt.xy;
  return result;
}

#endif
