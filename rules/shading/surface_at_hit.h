// The material at a hit, in the one order both backends apply it
// (docs/shading.md, "The material at a hit"): a backend fetches what the hit
// offers (the material's parameters, its textures' values, the surface's
// partials) and stores what this rule returns; every choice between them is
// made here.

#ifndef FACET_RULE_SHADING_SURFACE_AT_HIT
#define FACET_RULE_SHADING_SURFACE_AT_HIT

#include "rules/shading/brdf.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/textured_material.h"
#include "rules/shading/transmissive_continuation.h"
#include "rules/surface/tangent.h"

// The normals the surface gives at a hit, turned to face v. The hit is
// `outside` where v lies on the side the outward geometric normal points to.
struct FacingNormals {
  vec3 n;
  vec3 ng;
  bool outside;
};

FACET_FN FacingNormals facing_normals(vec3 n, vec3 ng, vec3 v) {
  FacingNormals f;
  f.outside = !(dot(ng, v) < real(0));
  f.n = f.outside ? n : -n;
  f.ng = f.outside ? ng : -ng;
  return f;
}

// A textured material's glTF factors, and which of its normal maps and
// directions are read at all.
struct TexturedFactors {
  vec3 base;
  real metallic;
  real roughness;
  bool normal_mapped;
  real normal_scale;
  real occlusion_strength;
  bool unlit;
  bool coat_normal_mapped;
  real coat_normal_scale;
  bool anisotropy_mapped;
  vec3 specular_color;  // KHR_materials_specular: F(0) of the index x specularColorFactor
  real specular;        // specularFactor
  bool film_thickness_mapped;   // KHR_materials_iridescence's thickness texture is read
  real film_thickness_minimum;  // its iridescenceThicknessMinimum, nanometres
  bool sheen_roughness_mapped;  // KHR_materials_sheen's roughness texture is read
};

// Each texture slot's value at a hit (1 where the slot is empty, or where the
// scene has no such layer), and the frames the two normal maps turn in: those
// of the coordinate sets they read.
struct MaterialTexels {
  vec3 base;  // times any vertex colour (glTF COLOR_0)
  vec3 metallic_roughness;
  vec3 normal;
  TextureFootprint normal_frame;
  UvMap normal_map;  // the normal map slot's transform (slot_uv_map)
  real occlusion;
  vec3 emission;
  real coat;
  real coat_roughness;
  vec3 coat_normal;
  TextureFootprint coat_normal_frame;
  UvMap coat_normal_map;
  vec3 sheen;
  vec3 anisotropy;
  real transmission;
  vec3 specular_color;  // sRGB
  real specular;        // A of specularTexture
  real iridescence;     // R of iridescenceTexture
  real iridescence_thickness;  // G of iridescenceThicknessTexture
  // Where the sheen's roughness is mapped: its alpha (textured_sheen_alpha)
  // and the albedo knots there, read between the rows about it.
  real sheen_alpha;
  vec4 sheen_albedo_near;
  vec4 sheen_albedo_far;
};

// What a backend fetched of the material at a hit.
struct HitMaterial {
  BrdfParams params;  // the material's own, before any texture
  vec3 emission;      // the material's own
  bool textured;
  TexturedFactors factors;
  MaterialTexels texels;
  bool transmissive;
  TransmissionParams transmission;
  vec2 anisotropy_rotation;  // cos and sin of the tangent's rotation about the normal
};

// The surface's first-order geometry, where an anisotropic lobe needs its
// tangent: dP/ds, dP/dt and the partials of the first set of texture
// coordinates (all zero where the surface has none); and, where the material
// takes a tangent at all, the mesh's (mesh_tangent; w = 0 where it has none).
struct HitPartials {
  vec3 dp_ds;
  vec3 dp_dt;
  vec2 duv_ds;
  vec2 duv_dt;
  vec4 tangent;
};

// The material at a hit as the lights and the environment see it.
struct SurfaceAtHit {
  BrdfParams params;
  vec3 n;  // shading normal, facing v; a normal map turned it
  vec3 ng;
  bool outside;
  real occlusion;  // the share of the environment's light that reaches it
  vec3 emission;   // what leaves towards v, under any coat
  TransmissionParams transmission;  // a transmissive material's, after its texture
};

// Parameters, then the textures (which may map the normal), then the side a
// transmissive interface is seen from, with a textured material's base
// colour and metallic mix (glTF), then the tangent about the final
// normal, then the coat over the emission (KHR_materials_clearcoat). The
// coat keeps the surface's own normal but for its own normal map.
FACET_FN SurfaceAtHit surface_at_hit(HitMaterial m, FacingNormals facing, vec3 v, HitPartials partials) {
  // Textures and tangents turn the surface as its outside shows it (there
  // the bitangent points up the image); a hit from inside sees that same
  // surface turned over.
  real side = facing.outside ? real(1) : real(-1);
  SurfaceAtHit s;
  s.params = m.params;
  s.params.clearcoat_normal = facing.n * side;
  s.n = facing.n * side;
  s.ng = facing.ng;
  s.outside = facing.outside;
  s.occlusion = real(1);
  s.emission = m.emission;
  s.transmission = m.transmission;
  vec2 anisotropy_direction = vec2(real(1), real(0));
  if (m.textured) {
    TexturedFactors f = m.factors;
    MaterialTexels t = m.texels;
    TexturedSurface textured =
        textured_surface(s.params, s.n, t.normal_frame, t.normal_map, f.base, f.metallic, f.roughness,
                         dielectric_specular_f0(f.specular_color, f.specular, t.specular_color, t.specular),
                         f.normal_scale, f.occlusion_strength, m.emission, t.base, t.metallic_roughness,
                         f.normal_mapped, t.normal, t.occlusion, t.emission, f.unlit, partials.tangent);
    textured = textured_layers(textured, t.coat_normal_frame, t.coat_normal_map, t.coat, t.coat_roughness,
                               f.coat_normal_mapped, t.coat_normal, f.coat_normal_scale, t.sheen, f.anisotropy_mapped,
                               t.anisotropy, partials.tangent);
    s.params = textured_film(textured.params, t.iridescence, f.film_thickness_mapped, t.iridescence_thickness,
                             f.film_thickness_minimum);
    if (f.sheen_roughness_mapped)
      s.params = textured_sheen(s.params, t.sheen_alpha, t.sheen_albedo_near, t.sheen_albedo_far);
    s.n = textured.n;
    s.occlusion = textured.occlusion;
    s.emission = textured.emission;
    anisotropy_direction = textured.anisotropy_direction;
  }
  vec3 outward = s.n;
  s.n = s.n * side;
  s.params.clearcoat_normal = s.params.clearcoat_normal * side;
  if (m.transmissive) {
    vec3 base = vec3(real(1), real(1), real(1));
    real metallic = real(0);
    if (m.textured) {
      base = m.factors.base * m.texels.base;
      metallic = m.factors.metallic * m.texels.metallic_roughness.z;
      s.transmission.transmission *= m.texels.transmission;
    }
    s.params = transmissive_brdf_params(s.params, s.transmission, s.outside, base, metallic);
  }
  if (s.params.anisotropy != real(0)) {
    vec2 rotation = turned_rotation(m.anisotropy_rotation, anisotropy_direction);
    s.params.tangent = anisotropy_tangent(outward, partials.tangent, partials.dp_ds, partials.dp_dt, partials.duv_ds,
                                          partials.duv_dt, rotation.x, rotation.y);
  }
  if (s.params.clearcoat != real(0))
    s.emission = s.emission * coat_transmittance(s.params, dot(s.params.clearcoat_normal, v));
  return s;
}

#endif
