// What a textured glTF material becomes at a hit (docs/shading.md, "Textures").

#ifndef FACET_RULE_SHADING_TEXTURED_MATERIAL
#define FACET_RULE_SHADING_TEXTURED_MATERIAL

#include "rules/math.h"
#include "rules/shading/brdf.h"
#include "rules/shading/sheen.h"
#include "rules/surface/tangent.h"
#include "rules/texture/texture_sampling.h"

// The half angle by which a camera ray's cone widens: one pixel's angle at
// the image centre, for an image `height` pixels high (Akenine-Möller et al.
// 2021, eq. 30).
FACET_FN real camera_cone_spread(real tan_half_fov_y, real height) {
  return atan(real(2) * tan_half_fov_y / height);
}

// The linear part of KHR_texture_transform, applied to a partial d(uv)/dx.
FACET_FN vec2 transform_uv_partial(vec2 d, real cos_rotation, real sin_rotation, vec2 scale) {
  return transform_uv(d, vec2(real(0), real(0)), cos_rotation, sin_rotation, scale);
}

// The same as a UvMap, for a tangent frame in the slot's coordinates.
FACET_FN UvMap slot_uv_map(real cos_rotation, real sin_rotation, vec2 scale) {
  UvMap m;
  m.u = transform_uv_partial(vec2(real(1), real(0)), cos_rotation, sin_rotation, scale);
  m.v = transform_uv_partial(vec2(real(0), real(1)), cos_rotation, sin_rotation, scale);
  return m;
}

// What a hit offers texture lookups: the texture coordinates and their
// partials, the position's partials over the patch's (s, t), and the ray
// cone's width there and the cosine at which it meets the surface.
struct TextureFootprint {
  vec2 uv;
  vec2 duv_ds;
  vec2 duv_dt;
  vec3 dp_ds;
  vec3 dp_dt;
  real cone_width;
  real cos_view;
};

// Where a slot of KHR_texture_transform (offset, rotation as cos and sin,
// scale) reads a texture of width x height texels: its coordinates and
// level of detail.
struct SlotLookup {
  vec2 uv;
  real lod;
};

FACET_FN SlotLookup slot_lookup(TextureFootprint f, vec2 offset, real cos_rotation, real sin_rotation, vec2 scale,
                                int width, int height) {
  SlotLookup l;
  l.uv = transform_uv(f.uv, offset, cos_rotation, sin_rotation, scale);
  l.lod = cone_texture_lod(f.cone_width, f.cos_view, f.dp_ds, f.dp_dt,
                           transform_uv_partial(f.duv_ds, cos_rotation, sin_rotation, scale),
                           transform_uv_partial(f.duv_dt, cos_rotation, sin_rotation, scale), width, height);
  return l;
}

// glTF's metallic-roughness mapping (docs/shading.md): base colour and
// metallic to c_diff and F(0) = mix(the dielectric's, base, metallic),
// perceptual roughness to alpha. The dielectric's F(0) is 0.04 unless
// KHR_materials_ior or KHR_materials_specular say otherwise
// (dielectric_specular_f0).
FACET_FN BrdfParams metallic_roughness_params(BrdfParams p, vec3 base, real metallic, real roughness,
                                              vec3 dielectric_f0) {
  p.diffuse = base * (real(1) - metallic);
  p.f0 = mix(dielectric_f0, base, metallic);
  p.alpha = roughness * roughness;
  return p;
}

// KHR_materials_specular's dielectric F(0) at a hit: min(F(0) of the index x
// specularColorFactor x specularColorTexture, 1) x specularFactor x
// specularTexture's alpha; `color_factor` is the first two's product.
FACET_FN vec3 dielectric_specular_f0(vec3 color_factor, real factor, vec3 color_texel, real texel) {
  return min(color_factor * color_texel, vec3(real(1), real(1), real(1))) * (factor * texel);
}

// The normal a tangent-space normal map's `texel` (RGB in [0, 1]) gives in
// frame f about unit normal n (texture_frame): n' = normalize(t x s + b y s
// + n z), (x, y, z) = 2 RGB - 1, `scale` glTF's normalTexture.scale. Returns
// n where the frame is undefined.
FACET_FN vec3 mapped_normal(vec3 n, TangentFrame f, vec3 texel, real scale) {
  if (!f.defined) return n;
  vec3 m = texel * real(2) - vec3(real(1), real(1), real(1));
  vec3 mapped = f.t * (m.x * scale) + f.b * (m.y * scale) + n * m.z;
  real mapped2 = dot(mapped, mapped);
  return mapped2 > real(0) ? mapped * inversesqrt(mapped2) : n;
}

// What an occlusion texture's red channel leaves of the environment's light
// (glTF: 1 + strength (occlusion - 1)).
FACET_FN real occlusion_factor(real occlusion, real strength) { return real(1) + strength * (occlusion - real(1)); }

// A textured material at a hit: its BRDF parameters, shading normal, the
// share of the environment's light that reaches it and the radiance it emits.
struct TexturedSurface {
  BrdfParams params;
  vec3 n;
  real occlusion;
  vec3 emission;
  vec2 anisotropy_direction;  // in the tangent frame, turned further by the material's rotation
};

// From the material's glTF factors and its slots' values (1 where a slot is
// empty; `normal_mapped` false keeps n): base colour RGB, metallic-roughness
// G roughness and B metallic, the normal map's RGB, occlusion R, emission RGB.
// An `unlit` material (KHR_materials_unlit, docs/gltf.md) emits its base
// colour instead; it reflects nothing by its models, not by this rule.
FACET_FN TexturedSurface textured_surface(BrdfParams p, vec3 n, TextureFootprint f, UvMap f_map, vec3 base_factor,
                                          real metallic_factor, real roughness_factor, vec3 dielectric_f0,
                                          real normal_scale, real occlusion_strength, vec3 emission_factor, vec3 base,
                                          vec3 metallic_roughness, bool normal_mapped, vec3 normal_texel,
                                          real occlusion, vec3 emission, bool unlit, vec4 mesh_tangent) {
  TexturedSurface surface;
  surface.params = metallic_roughness_params(p, base_factor * base, metallic_factor * metallic_roughness.z,
                                             roughness_factor * metallic_roughness.y, dielectric_f0);
  if (normal_mapped)
    surface.n = mapped_normal(n, texture_frame(n, mesh_tangent, f.dp_ds, f.dp_dt, f.duv_ds, f.duv_dt, f_map),
                              normal_texel, normal_scale);
  else
    surface.n = n;
  surface.occlusion = occlusion_factor(occlusion, occlusion_strength);
  surface.emission = unlit ? base_factor * base : emission_factor * emission;
  surface.anisotropy_direction = vec2(real(1), real(0));
  return surface;
}

// The layers' textures at a hit (docs/gltf.md), each value 1 where its slot
// is empty (the normal map and the direction are read only where `_mapped`):
// KHR_materials_clearcoat's strength (R of `coat`) and roughness
// (G of `coat_roughness`) scale the factors, and its normal map turns the
// coat's own normal in the frame of footprint `coat_f`; KHR_materials_sheen's
// colour (sRGB) scales the factor; KHR_materials_anisotropy's RG is a
// direction in the tangent frame, from [0, 1] to [-1, 1], and its B scales
// the strength.
FACET_FN TexturedSurface textured_layers(TexturedSurface s, TextureFootprint coat_f, UvMap coat_map, real coat,
                                         real coat_roughness, bool coat_mapped, vec3 coat_normal_texel,
                                         real coat_normal_scale, vec3 sheen, bool anisotropy_mapped, vec3 anisotropy,
                                         vec4 mesh_tangent) {
  s.params.clearcoat *= coat;
  s.params.clearcoat_alpha *= sqr(coat_roughness);
  vec3 coat_n = s.params.clearcoat_normal;
  if (coat_mapped)
    s.params.clearcoat_normal = mapped_normal(
        coat_n, texture_frame(coat_n, mesh_tangent, coat_f.dp_ds, coat_f.dp_dt, coat_f.duv_ds, coat_f.duv_dt, coat_map),
        coat_normal_texel, coat_normal_scale);
  s.params.sheen_color *= sheen;
  if (!anisotropy_mapped) return s;
  s.params.anisotropy *= anisotropy.z;
  vec2 d = vec2(anisotropy.x, anisotropy.y) * real(2) - vec2(real(1), real(1));
  real length2 = dot(d, d);
  s.anisotropy_direction = length2 > real(0) ? d * inversesqrt(length2) : vec2(real(1), real(0));
  return s;
}

// KHR_materials_iridescence's textures at a hit: R of `film` scales the
// film's factor and, where a thickness texture is read, its G places the
// thickness between `thinnest` and the material's own, the extension's
// maximum.
FACET_FN BrdfParams textured_film(BrdfParams p, real film, bool thickness_mapped, real thickness, real thinnest) {
  p.iridescence *= film;
  if (thickness_mapped) p.iridescence_thickness = mix(thinnest, p.iridescence_thickness, thickness);
  return p;
}

// KHR_materials_sheen's roughness texture at a hit: A of its texel scales
// the factor (a perceptual roughness) into the hit's sheen alpha.
FACET_FN real textured_sheen_alpha(real roughness_factor, real texel) { return sqr(roughness_factor * texel); }

// The sheen of textured alpha `alpha` (textured_sheen_alpha), its albedo
// knots read between the rows about it (sheen_rows_at) by the backend.
FACET_FN BrdfParams textured_sheen(BrdfParams p, real alpha, vec4 albedo_near, vec4 albedo_far) {
  p.sheen_alpha = alpha;
  p.sheen_albedo_near = albedo_near;
  p.sheen_albedo_far = albedo_far;
  return p;
}

// A rotation (cos, sin) turned further by `direction` (a unit vector, the
// angle it makes with the first axis).
FACET_FN vec2 turned_rotation(vec2 rotation, vec2 direction) {
  return vec2(rotation.x * direction.x - rotation.y * direction.y, rotation.y * direction.x + rotation.x * direction.y);
}

#endif
