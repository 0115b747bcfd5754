// What a hit's material offers surface_at_hit (rules/shading/surface_at_hit.h):
// the material's own parameters, its textures' values at the hit and its
// transmission, as engine/cpu's ReferenceScene::hitMaterial and
// textured_hit.cpp fetch them. Included by surface.comp, after its
// specialization constants and bindings and the common sampling helpers.
#ifndef FACET_RAYCAST_HIT_MATERIAL_GLSL
#define FACET_RAYCAST_HIT_MATERIAL_GLSL

// The sheen's albedo knots at SHEEN_ROWS alphas, near and far in turn
// (materials::sheenAlbedoRows): where a sheen's roughness is textured.
layout(set = 0, binding = 35) uniform samplerBuffer sheenAlbedoRows;

// The material's own parameters, before any texture; a lobe the scene has
// nowhere stays off.
BrdfParams brdf_params(MaterialRecord m) {
  BrdfParams p;
  p.d_model = D_MODEL >= 0 ? D_MODEL : m.dModel;
  p.g_model = G_MODEL >= 0 ? G_MODEL : m.gModel;
  p.f_model = F_MODEL >= 0 ? F_MODEL : m.fModel;
  p.alpha = m.alpha;
  p.f0 = vec3(m.f0R, m.f0G, m.f0B);
  p.eta = vec3(m.etaR, m.etaG, m.etaB);
  p.k = vec3(m.kR, m.kG, m.kB);
  p.metallic = 0.0;  // a textured transmissive material's, set per hit
  p.diffuse = vec3(m.diffuseR, m.diffuseG, m.diffuseB);
  p.anisotropy = ANISOTROPY == 1 ? m.anisotropy : 0.0;
  p.tangent = vec3(1.0, 0.0, 0.0);
  p.clearcoat = CLEARCOAT == 1 ? m.clearcoat : 0.0;
  p.clearcoat_alpha = m.clearcoatAlpha;
  p.clearcoat_normal = vec3(0.0, 0.0, 1.0);
  p.sheen_color = SHEEN == 1 ? vec3(m.sheenR, m.sheenG, m.sheenB) : vec3(0.0);
  p.sheen_alpha = m.sheenAlpha;
  p.sheen_albedo_near = vec4(m.sheenAlbedo0, m.sheenAlbedo1, m.sheenAlbedo2, m.sheenAlbedo3);
  p.sheen_albedo_far = vec4(m.sheenAlbedo4, m.sheenAlbedo5, m.sheenAlbedo6, m.sheenAlbedo7);
  p.iridescence = IRIDESCENCE == 1 ? m.iridescence : 0.0;
  p.iridescence_ior = m.iridescenceIor;
  p.iridescence_thickness = m.iridescenceThickness;
  return p;
}

// Whether the scene has a layer whose textures a hit reads.
const bool LAYERS = CLEARCOAT == 1 || SHEEN == 1 || ANISOTROPY == 1;

TexturedFactors textured_factors(MaterialRecord m) {
  return TexturedFactors(vec3(m.baseR, m.baseG, m.baseB), m.metallic, m.roughness,
                         m.normalTexture.texture != FACET_NO_TEXTURE, m.normalScale, m.occlusionStrength,
                         m.unlit == 1u, LAYERS && m.clearcoatNormalTexture.texture != FACET_NO_TEXTURE,
                         m.clearcoatNormalScale, LAYERS && m.anisotropyTexture.texture != FACET_NO_TEXTURE,
                         vec3(m.specularR, m.specularG, m.specularB), m.specular,
                         IRIDESCENCE == 1 && m.iridescenceThicknessTexture.texture != FACET_NO_TEXTURE,
                         m.iridescenceThicknessMinimum,
                         SHEEN == 1 && m.sheenRoughnessTexture.texture != FACET_NO_TEXTURE);
}

// The footprint a slot reads: that of the coordinate set it names.
TextureFootprint slot_footprint(TextureSlotRecord slot, TextureFootprint f0, TextureFootprint f1) {
  return slot.texCoord == 1u ? f1 : f0;
}

// The transform a slot reads its coordinates through, as a tangent frame
// takes it.
UvMap slot_map(TextureSlotRecord slot) {
  return slot_uv_map(slot.cosRotation, slot.sinRotation, vec2(slot.scaleX, slot.scaleY));
}

// Every slot of textured material m at a hit on patch `record` (at point p)
// of an object with face-varying `channels`, seen along `direction` from
// distance t, of geometric normal ng (engine/cpu/textured_hit.h's
// materialTexels).
MaterialTexels material_texels(MaterialRecord m, PatchRecord record, uint channels, PatchSample p, HitRecord hit,
                               vec3 ng, vec3 direction) {
  float cone = hit.t * camera_cone_spread(frame.tanHalfFovY, frame.height);
  SurfaceTexcoord uv = surface_texcoord(channel_texel(record.firstTexcoord, channels, FACET_CHANNEL_TEXCOORD0), hit.s,
                                        hit.tParam);
  TextureFootprint f0 = TextureFootprint(uv.uv, uv.ds, uv.dt, p.ds, p.dt, cone, abs(dot(ng, direction)));
  TextureFootprint f1 = f0;
  if (CHANNELS == 1 && (channels & FACET_CHANNEL_TEXCOORD1) != 0u) {
    SurfaceTexcoord uv1 = surface_texcoord(channel_texel(record.firstTexcoord, channels, FACET_CHANNEL_TEXCOORD1),
                                           hit.s, hit.tParam);
    f1 = TextureFootprint(uv1.uv, uv1.ds, uv1.dt, p.ds, p.dt, cone, abs(dot(ng, direction)));
  }
  MaterialTexels t;
  t.base = slot_value(m.baseColorTexture, slot_footprint(m.baseColorTexture, f0, f1)).rgb;
  if (CHANNELS == 1)
    t.base *= surface_color(channel_texel(record.firstTexcoord, channels, FACET_CHANNEL_COLOR), hit.s, hit.tParam);
  t.metallic_roughness = slot_value(m.metallicRoughnessTexture, slot_footprint(m.metallicRoughnessTexture, f0, f1)).rgb;
  t.normal_frame = slot_footprint(m.normalTexture, f0, f1);
  t.normal_map = slot_map(m.normalTexture);
  t.normal = slot_value(m.normalTexture, t.normal_frame).rgb;
  t.occlusion = slot_value(m.occlusionTexture, slot_footprint(m.occlusionTexture, f0, f1)).r;
  t.emission = slot_value(m.emissiveTexture, slot_footprint(m.emissiveTexture, f0, f1)).rgb;
  t.specular_color = slot_value(m.specularColorTexture, slot_footprint(m.specularColorTexture, f0, f1)).rgb;
  t.specular = slot_value(m.specularTexture, slot_footprint(m.specularTexture, f0, f1)).a;
  t.coat = 1.0;
  t.coat_roughness = 1.0;
  t.coat_normal = vec3(1.0);
  t.coat_normal_frame = f0;
  t.coat_normal_map = t.normal_map;
  t.sheen = vec3(1.0);
  t.anisotropy = vec3(1.0);
  t.transmission =
      TRANSMISSION == 1 ? slot_value(m.transmissionTexture, slot_footprint(m.transmissionTexture, f0, f1)).r : 1.0;
  t.iridescence = 1.0;
  t.iridescence_thickness = 1.0;
  t.sheen_alpha = 0.0;
  t.sheen_albedo_near = vec4(0.0);
  t.sheen_albedo_far = vec4(0.0);
  if (IRIDESCENCE == 1) {
    t.iridescence = slot_value(m.iridescenceTexture, slot_footprint(m.iridescenceTexture, f0, f1)).r;
    t.iridescence_thickness =
        slot_value(m.iridescenceThicknessTexture, slot_footprint(m.iridescenceThicknessTexture, f0, f1)).g;
  }
  if (!LAYERS) return t;
  t.coat = slot_value(m.clearcoatTexture, slot_footprint(m.clearcoatTexture, f0, f1)).r;
  t.coat_roughness = slot_value(m.clearcoatRoughnessTexture, slot_footprint(m.clearcoatRoughnessTexture, f0, f1)).g;
  t.coat_normal_frame = slot_footprint(m.clearcoatNormalTexture, f0, f1);
  t.coat_normal_map = slot_map(m.clearcoatNormalTexture);
  t.coat_normal = slot_value(m.clearcoatNormalTexture, t.coat_normal_frame).rgb;
  t.sheen = slot_value(m.sheenColorTexture, slot_footprint(m.sheenColorTexture, f0, f1)).rgb;
  if (SHEEN == 1 && m.sheenRoughnessTexture.texture != FACET_NO_TEXTURE) {
    t.sheen_alpha = textured_sheen_alpha(
        m.sheenRoughnessFactor, slot_value(m.sheenRoughnessTexture, slot_footprint(m.sheenRoughnessTexture, f0, f1)).a);
    SheenRows at = sheen_rows_at(t.sheen_alpha);
    int first = 2 * at.first;
    t.sheen_albedo_near =
        mix(texelFetch(sheenAlbedoRows, first), texelFetch(sheenAlbedoRows, first + 2), at.weight);
    t.sheen_albedo_far =
        mix(texelFetch(sheenAlbedoRows, first + 1), texelFetch(sheenAlbedoRows, first + 3), at.weight);
  }
  t.anisotropy = slot_value(m.anisotropyTexture, slot_footprint(m.anisotropyTexture, f0, f1)).rgb;
  return t;
}

// What material m offers surface_at_hit at a hit at point p (evaluated only
// where a texture or the tangent needs it).
HitMaterial hit_material(MaterialRecord m, PatchRecord record, uint channels, PatchSample p, HitRecord hit, vec3 ng,
                         vec3 direction) {
  HitMaterial h;
  h.params = brdf_params(m);
  h.emission = vec3(m.emissionR, m.emissionG, m.emissionB);
  h.textured = TEXTURES == 1 && m.textured == 1u;
  if (h.textured) {
    h.factors = textured_factors(m);
    h.texels = material_texels(m, record, channels, p, hit, ng, direction);
  }
  h.transmissive = TRANSMISSION == 1 && m.transmissive == 1u;
  h.transmission = transmission_params(m);
  h.anisotropy_rotation = vec2(m.anisotropyCos, m.anisotropySin);
  return h;
}

// The mesh's tangent at the hit where its object carries tangents (only
// where its material takes one), and the partials an anisotropic lobe's
// tangent is made of at p where the material is anisotropic (engine/cpu's
// hitPartials).
HitPartials hit_partials(bool anisotropic, ObjectRange range, PatchRecord record, PatchSample p, HitRecord hit) {
  HitPartials partials = HitPartials(vec3(0.0), vec3(0.0), vec2(0.0), vec2(0.0), vec4(0.0));
  if ((range.flags & FACET_OBJECT_TANGENTS) != 0u) {
    int i = int(record.firstNormal) + 4;
    partials.tangent = mesh_tangent(texelFetch(authoredNormals, i), texelFetch(authoredNormals, i + 1),
                                    texelFetch(authoredNormals, i + 2), texelFetch(authoredNormals, i + 3), hit.s,
                                    hit.tParam);
  }
  if (!anisotropic) return partials;
  SurfaceTexcoord uv = surface_texcoord(channel_texel(record.firstTexcoord, range.channels, FACET_CHANNEL_TEXCOORD0),
                                        hit.s, hit.tParam);
  partials.dp_ds = p.ds;
  partials.dp_dt = p.dt;
  partials.duv_ds = uv.ds;
  partials.duv_dt = uv.dt;
  return partials;
}

#endif
