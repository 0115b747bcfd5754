// The tangents of a hit (docs/shading.md, "Anisotropy" and "The tangent
// frame"): the field an anisotropic lobe is oriented by, a mesh's own
// tangent, and the frame tangent-space textures turn in.

#ifndef FACET_RULE_SURFACE_TANGENT
#define FACET_RULE_SURFACE_TANGENT

#include "rules/shading/microfacet.h"

// The parametric tangent field: the surface's dP/ds made orthogonal to the
// shading normal n (Gram-Schmidt) and turned about n by the material's
// rotation (cos, sin). Where dP/ds vanishes or lies along n (a degenerate
// patch corner), dP/dt turned a quarter about n stands in, as ds x dt ~ n
// makes dt x n point along ds; where both fail, the arbitrary frame's.
FACET_FN vec3 surface_tangent(vec3 n, vec3 dp_ds, vec3 dp_dt, real cos_rotation, real sin_rotation) {
  vec3 t = dp_ds - n * dot(n, dp_ds);
  if (!(dot(t, t) > real(0))) t = cross(dp_dt, n);
  real length2 = dot(t, t);
  t = length2 > real(0) ? t * inversesqrt(length2) : frame_from_normal(n).t;
  return t * cos_rotation + cross(n, t) * sin_rotation;
}

// A mesh's tangent at patch-local (s, t) (ControlCage::faceVertexTangents):
// its corner tangents (counter-clockwise from (0, 0), as the patch's points)
// interpolated bilinearly, xyz unnormalized as MikkTSpace's pixel stage
// takes it, and w the sign that makes w (n x t) the bitangent pointing up
// the image.
FACET_FN vec4 mesh_tangent(vec4 t00, vec4 t10, vec4 t11, vec4 t01, real s, real t) {
  vec4 m = (real(1) - s) * (real(1) - t) * t00 + s * (real(1) - t) * t10 + s * t * t11 + (real(1) - s) * t * t01;
  return vec4(m.x, m.y, m.z, m.w < real(0) ? real(-1) : real(1));
}

// The linear part of the map from a surface's texture coordinates to those
// a texture slot reads (KHR_texture_transform's rotation and scale): the
// images of the u and v axes.
struct UvMap {
  vec2 u;
  vec2 v;
};

FACET_FN vec2 apply_uv_map(UvMap m, vec2 d) { return m.u * d.x + m.v * d.y; }

// The frame a tangent-space texture (a normal map, an anisotropy direction)
// turns in at a hit of unit normal n: t along dP/du' and b the bitangent
// that points up the image, both orthogonal to n, where (u', v') are the
// coordinates the texture reads, the surface's mapped by `map`
// (docs/shading.md, "The tangent frame"). The surface's dP/du and dP/dv are
// the mesh's tangent where it has one (w != 0) and its bitangent w (n x t)
// reversed (glTF's v runs down the image), else solved from the partials;
// b is n x t turned against dP/dv', as glTF-Sample-Viewer builds it from
// derivatives. Undefined where neither gives a direction off n.
struct TangentFrame {
  vec3 t;
  vec3 b;
  bool defined;
};

FACET_FN TangentFrame texture_frame(vec3 n, vec4 tangent, vec3 dp_ds, vec3 dp_dt, vec2 duv_ds, vec2 duv_dt, UvMap map) {
  TangentFrame f;
  f.b = vec3(real(0), real(0), real(0));
  f.defined = false;
  vec3 along = vec3(tangent.x, tangent.y, tangent.z);
  vec3 mesh_t = along - n * dot(n, along);
  real length2 = dot(mesh_t, mesh_t);
  if (tangent.w != real(0) && length2 > real(0)) {
    // The mesh's frame as partials over (u, v) themselves.
    dp_ds = mesh_t * inversesqrt(length2);
    dp_dt = -(cross(n, dp_ds) * tangent.w);
    duv_ds = vec2(real(1), real(0));
    duv_dt = vec2(real(0), real(1));
  }
  duv_ds = apply_uv_map(map, duv_ds);
  duv_dt = apply_uv_map(map, duv_dt);
  real det = duv_ds.x * duv_dt.y - duv_ds.y * duv_dt.x;
  if (det == real(0)) return f;
  vec3 dp_du = (dp_ds * duv_dt.y - dp_dt * duv_ds.y) / det;
  vec3 dp_dv = (dp_dt * duv_ds.x - dp_ds * duv_dt.x) / det;
  f.t = dp_du - n * dot(n, dp_du);
  length2 = dot(f.t, f.t);
  if (!(length2 > real(0))) return f;
  f.t = f.t * inversesqrt(length2);
  f.b = cross(n, f.t);
  if (dot(f.b, dp_dv) > real(0)) f.b = -f.b;
  f.defined = true;
  return f;
}

// The tangent of an anisotropic lobe (KHR_materials_anisotropy): texture
// space's t turned towards its b by the rotation, so that a mirrored layout
// turns the other way, as the direction drawn in the texture does on the
// surface; surface_tangent's parametric field where the hit has no texture
// frame.
FACET_FN vec3 anisotropy_tangent(vec3 n, vec4 tangent, vec3 dp_ds, vec3 dp_dt, vec2 duv_ds, vec2 duv_dt,
                                 real cos_rotation, real sin_rotation) {
  UvMap same;
  same.u = vec2(real(1), real(0));
  same.v = vec2(real(0), real(1));
  TangentFrame f = texture_frame(n, tangent, dp_ds, dp_dt, duv_ds, duv_dt, same);
  if (f.defined) return f.t * cos_rotation + f.b * sin_rotation;
  return surface_tangent(n, dp_ds, dp_dt, cos_rotation, sin_rotation);
}

#endif
