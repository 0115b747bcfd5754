// Per camera ray that hit: the surface point, its limit normal and, from the
// centre ray, the pixel's AOVs; per light of a shaded sample, the unshadowed
// radiance pi f(l, v) c_light (n.l) and the shadow ray that decides it; then
// the environment's share (docs/rendering.md): prefiltered, or sampled or
// filtered without occlusion, in one slot that no ray tests; sampled or
// filtered with occlusion, one slot and shadow ray per environment and per
// BRDF sample. A ray that
// misses writes the miss AOVs and, with an environment, the radiance it
// sees in the environment's first slot. Every slot gets its contribution;
// the shadow rays that decide some of them are appended to one compacted
// list (counters.shadowRays), so the shadow pass costs nothing for slots,
// samples or pixels that need no ray.
//
// Specialization: LIGHT_COUNT, ENVIRONMENT
// (0 none, 1 sampled, 2 prefiltered, 3 filtered), OCCLUSION (sampled,
// filtered: 1 traces the environment's shadow rays), ENVIRONMENT_SAMPLES
// (filtered: 1 adds the environment technique), the BRDF models D_MODEL, G_MODEL,
// F_MODEL, each -1 when the scene's materials use several (the model is then
// read per material), TEXTURES (1 when some material reads a texture) and
// EMISSION (1 when some material emits: each ray's last slot holds it) and
// COMPENSATION (1 when some material's specular lobe is energy-compensated).
// PATHS (docs/rendering.md, "Paths"): 1 writes each camera ray's path state
// (its first vertex, or none) and counts the rays that hit; with
// frame.pathVertex > 0 the invocations are those of the compacted
// continuation rays instead (dispatched indirectly), each shading the vertex
// it hits into its camera ray's slots, with the environment pairs of that
// vertex's seed, and moving its path on to that vertex (a miss ends it).
// TRANSMISSION (docs/rendering.md, "Transmission and absorption"): 1 when
// some material transmits; D at a vertex of one takes
// transmissive_brdf_params by the side v lies on, a continuation ray's path
// takes Beer-Lambert's factor over the segment it travelled, and one that
// went through its last surface and misses sees the environment in the
// environment's slot (gather adds it).
// LOBE_LIMITS (docs/rendering.md, "Limits per lobe kind"): 1 when the scene
// sets one; a continuation ray's path keeps its counts per lobe kind.
// ANISOTROPY (docs/shading.md, "Anisotropy"): 1 when some material is
// anisotropic; its hits evaluate the tangent field, and 0 keeps every lobe
// on the isotropic path.
// CLEARCOAT (docs/shading.md, "Clear coat"): 1 when some material has a
// clear coat; 0 keeps every material on the bare base's path.
// SHEEN (docs/shading.md, "Sheen"): 1 when some material has a sheen; 0
// keeps every material on the path without one.
// CHANNELS (docs/rendering.md, "Texture coordinates and vertex colours"): 1
// when some object has vertex colours or a second set of texture
// coordinates; 0 evaluates neither.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/common/scene_bindings.glsl"
#include "compute/raycast/common/ray.glsl"
#include "rules/language.glsl"
#include "rules/camera/sample_plan.h"
#include "rules/environment/filtered_environment.h"
#include "rules/environment/sampled_environment.h"
#include "rules/environment/split_sum.h"
#include "rules/shading/absorption.h"
#include "rules/shading/brdf.h"
#include "rules/shading/brdf_sampling.h"
#include "rules/shading/clearcoat.h"
#include "rules/shading/domain.h"
#include "rules/shading/lights.h"
#include "rules/shading/textured_material.h"
#include "rules/shading/transmissive_continuation.h"
#include "rules/surface/authored_normal.h"
#include "rules/surface/tangent.h"

layout(constant_id = 1) const int LIGHT_COUNT = 1;
layout(constant_id = 2) const int D_MODEL = -1;
layout(constant_id = 3) const int G_MODEL = -1;
layout(constant_id = 4) const int F_MODEL = -1;
layout(constant_id = 5) const int ENVIRONMENT = 0;
layout(constant_id = 6) const int OCCLUSION = 1;
layout(constant_id = 7) const int ENVIRONMENT_SAMPLES = 0;
layout(constant_id = 8) const int TEXTURES = 0;
layout(constant_id = 9) const int EMISSION = 0;
layout(constant_id = 10) const int COMPENSATION = 0;
layout(constant_id = 11) const int PATHS = 0;
layout(constant_id = 12) const int TRANSMISSION = 0;
layout(constant_id = 13) const int LOBE_LIMITS = 0;
layout(constant_id = 14) const int ANISOTROPY = 0;
layout(constant_id = 15) const int CLEARCOAT = 0;
layout(constant_id = 16) const int SHEEN = 0;
layout(constant_id = 17) const int CHANNELS = 0;

layout(set = 0, binding = 9, std430) readonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 11, std430) readonly buffer Materials { MaterialRecord materials[]; };
layout(set = 0, binding = 12, std430) readonly buffer Lights { LightRecord lights[]; };
layout(set = 0, binding = 13, std430) writeonly buffer Aovs { PixelAovs aovs[]; };
layout(set = 0, binding = 14, std430) writeonly buffer ShadowRays { ShadowRayRecord shadowRays[]; };
layout(set = 0, binding = 15, std430) writeonly buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 27) uniform samplerBuffer authoredNormals;
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 32, std430) buffer PathStates { PathState pathStates[]; };
layout(set = 0, binding = 33, std430) readonly buffer PathRays { PathRayRecord pathRays[]; };

#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/shading/limit_normal.glsl"
#include "compute/raycast/common/texcoord.glsl"
#include "compute/raycast/shading/environment.glsl"
#include "compute/raycast/common/camera_rays.glsl"
#include "compute/raycast/common/textures.glsl"
#include "compute/raycast/shading/energy_compensation.glsl"
#include "compute/raycast/common/path_state.glsl"

// The shading normal: a mesh's authored normals interpolated where it has
// them (turned to the side of the surface's normal `limit`), else `limit`
// (engine/cpu/limit_normal.h).
vec3 shading_normal(PatchRecord record, float s, float t, vec3 limit) {
  if (record.firstNormal == FACET_NO_NORMALS) return limit;
  int i = int(record.firstNormal);
  vec3 n = authored_normal(texelFetch(authoredNormals, i).xyz, texelFetch(authoredNormals, i + 1).xyz,
                           texelFetch(authoredNormals, i + 2).xyz, texelFetch(authoredNormals, i + 3).xyz, s, t);
  if (n == vec3(0.0)) return limit;
  return dot(n, limit) < 0.0 ? -n : n;
}

BrdfParams brdf_params(uint index) {
  MaterialRecord m = materials[index];
  BrdfParams p;
  p.d_model = D_MODEL >= 0 ? D_MODEL : m.dModel;
  p.g_model = G_MODEL >= 0 ? G_MODEL : m.gModel;
  p.f_model = F_MODEL >= 0 ? F_MODEL : m.fModel;
  p.alpha = m.alpha;
  p.f0 = vec3(m.f0R, m.f0G, m.f0B);
  p.eta = vec3(m.etaR, m.etaG, m.etaB);
  p.k = vec3(m.kR, m.kG, m.kB);
  p.diffuse = vec3(m.diffuseR, m.diffuseG, m.diffuseB);
  p.anisotropy = ANISOTROPY == 1 ? m.anisotropy : 0.0;
  p.tangent = vec3(1.0, 0.0, 0.0);  // set per hit from the tangent field where anisotropic
  p.clearcoat = CLEARCOAT == 1 ? m.clearcoat : 0.0;
  p.clearcoat_alpha = m.clearcoatAlpha;
  p.clearcoat_normal = vec3(0.0, 0.0, 1.0);  // set per hit: the normal before any normal map
  p.sheen_color = SHEEN == 1 ? vec3(m.sheenR, m.sheenG, m.sheenB) : vec3(0.0);
  p.sheen_alpha = m.sheenAlpha;
  p.sheen_albedo_near = vec4(m.sheenAlbedo0, m.sheenAlbedo1, m.sheenAlbedo2, m.sheenAlbedo3);
  p.sheen_albedo_far = vec4(m.sheenAlbedo4, m.sheenAlbedo5, m.sheenAlbedo6, m.sheenAlbedo7);
  return p;
}

// A slot whose radiance arrives without a test.
void write_unshadowed(uint slot, vec3 radiance) { contributions[slot] = vec4(radiance, 0.0); }

// A slot whose radiance arrives from `direction` unless something lies
// along the shadow ray from `position` up to tMax; the shadow pass clears it
// then.
void write_shadowed(uint slot, vec3 radiance, vec3 position, vec3 ng, vec3 direction, float tMax) {
  contributions[slot] = vec4(radiance, 0.0);
  vec3 origin = shadow_ray_origin(position, ng, frame.shadowOffset);
  shadowRays[atomicAdd(counters.shadowRays, 1u)] = ShadowRayRecord(
      RayRecord(origin.x, origin.y, origin.z, frame.shadowOffset, direction.x, direction.y, direction.z, tMax), slot);
}

// A textured material at a hit on patch `record` of points `c`, of an
// object with face-varying `channels`, seen along `direction` from distance
// t, with shading normal n and geometric normal ng facing the eye (the CPU
// reference's ReferenceScene::texturedSurface).
TexturedSurface textured_hit(MaterialRecord m, PatchRecord record, uint channels, ControlPoints c, HitRecord hit,
                             BrdfParams params, vec3 n, vec3 ng, vec3 direction) {
  PatchSample p = evaluate_patch(c, hit.s, hit.tParam);
  float cone = hit.t * camera_cone_spread(frame.tanHalfFovY, frame.height);
  SurfaceTexcoord uv = surface_texcoord(channel_texel(record.firstTexcoord, channels, FACET_CHANNEL_TEXCOORD0), hit.s,
                                        hit.tParam);
  TextureFootprint f = TextureFootprint(uv.uv, uv.ds, uv.dt, p.ds, p.dt, cone, abs(dot(ng, direction)));
  TextureFootprint f1 = f;
  if (CHANNELS == 1 && (channels & FACET_CHANNEL_TEXCOORD1) != 0u) {
    SurfaceTexcoord uv1 = surface_texcoord(channel_texel(record.firstTexcoord, channels, FACET_CHANNEL_TEXCOORD1),
                                           hit.s, hit.tParam);
    f1 = TextureFootprint(uv1.uv, uv1.ds, uv1.dt, p.ds, p.dt, cone, abs(dot(ng, direction)));
  }
  // A vertex colour multiplies the base colour as its texture does (glTF
  // COLOR_0); a normal map's frame follows the coordinates it reads.
  vec3 base = slot_value(m.baseColorTexture, m.baseColorTexture.texCoord == 1u ? f1 : f).rgb;
  if (CHANNELS == 1)
    base *= surface_color(channel_texel(record.firstTexcoord, channels, FACET_CHANNEL_COLOR), hit.s, hit.tParam);
  TextureFootprint fn = m.normalTexture.texCoord == 1u ? f1 : f;
  TexturedSurface surface = textured_surface(
      params, n, fn, vec3(m.baseR, m.baseG, m.baseB), m.metallic, m.roughness, m.normalScale, m.occlusionStrength,
      vec3(m.emissionR, m.emissionG, m.emissionB), base,
      slot_value(m.metallicRoughnessTexture, m.metallicRoughnessTexture.texCoord == 1u ? f1 : f).rgb,
      m.normalTexture.texture != FACET_NO_TEXTURE, slot_value(m.normalTexture, fn).rgb,
      slot_value(m.occlusionTexture, m.occlusionTexture.texCoord == 1u ? f1 : f).r,
      slot_value(m.emissiveTexture, m.emissiveTexture.texCoord == 1u ? f1 : f).rgb, m.unlit == 1u);
  if (CLEARCOAT == 0 && SHEEN == 0 && ANISOTROPY == 0) return surface;
  TextureFootprint fc = m.clearcoatNormalTexture.texCoord == 1u ? f1 : f;
  return textured_layers(surface, fc, slot_value(m.clearcoatTexture, m.clearcoatTexture.texCoord == 1u ? f1 : f).r,
                         slot_value(m.clearcoatRoughnessTexture, m.clearcoatRoughnessTexture.texCoord == 1u ? f1 : f).g,
                         m.clearcoatNormalTexture.texture != FACET_NO_TEXTURE,
                         slot_value(m.clearcoatNormalTexture, fc).rgb, m.clearcoatNormalScale,
                         slot_value(m.sheenColorTexture, m.sheenColorTexture.texCoord == 1u ? f1 : f).rgb,
                         m.anisotropyTexture.texture != FACET_NO_TEXTURE,
                         slot_value(m.anisotropyTexture, m.anisotropyTexture.texCoord == 1u ? f1 : f).rgb);
}

// Sampled or filtered method, one sample of either technique: its share for
// radiance `incoming`, and with OCCLUSION its shadow ray for `slot`.
void environment_sample(uint slot, BrdfParams params, vec3 specular_scale, vec3 position, vec3 n, vec3 ng, vec3 v,
                        MisSample s, vec3 incoming, inout vec3 unshadowed) {
  bool arrives = mis_sample_arrives(s, n, ng);
  vec3 radiance =
      arrives ? mis_sample_share(params, n, v, s, incoming, frame.environmentSamples, specular_scale) : vec3(0.0);
  if (OCCLUSION == 0)
    unshadowed += radiance;
  else if (arrives)
    write_shadowed(slot, radiance, position, ng, s.direction, INFINITE_DISTANCE);
  else
    write_unshadowed(slot, vec3(0.0));
}

// The environment's slots from `first` on, its light scaled by `occlusion`.
void shade_environment(uint first, uint pixel, uint sample_index, uint material, BrdfParams params,
                       vec3 specular_scale, vec3 position, vec3 n, vec3 ng, vec3 v, float occlusion) {
  if (ENVIRONMENT == 2) {
    float nv = dot(n, v);
    if (nv <= COS_EPSILON) {  // nothing to look up (the lobe may not even exist)
      write_unshadowed(first, vec3(0.0));
      return;
    }
    float alpha = isotropic_equivalent_alpha(params);
    vec3 lobe = split_sum_direction(anisotropic_bent_normal(params, n, v), v, alpha);
    vec3 prefiltered = prefiltered_radiance(to_map(lobe), alpha);
    vec2 dfg = dfg_lookup(materials[material].dfgTable, nv, alpha);
    vec3 irradiance = irradiance_over_pi(to_map(n));
    vec3 radiance;
    if (CLEARCOAT == 1 && params.clearcoat != 0.0) {
      vec3 nc = params.clearcoat_normal;
      float nv_coat = dot(nc, v), alpha_coat = params.clearcoat_alpha;
      vec3 coat_lobe = split_sum_direction(nc, v, alpha_coat);
      radiance = coated_split_sum(params, nv, prefiltered, dfg, irradiance, specular_scale, nv_coat,
                                  prefiltered_radiance(to_map(coat_lobe), alpha_coat),
                                  dfg_lookup(materials[material].coatDfgTable, nv_coat, alpha_coat));
    } else {
      radiance = split_sum(params, nv, prefiltered, dfg, irradiance, specular_scale);
    }
    write_unshadowed(first, occlusion * frame.environmentIntensity * radiance);
    return;
  }
  // Per pair, the environment technique's slot (if drawn), then the BRDF technique's.
  bool with_environment = ENVIRONMENT == 1 || ENVIRONMENT_SAMPLES == 1;
  uint stride = with_environment ? 2u : 1u;
  vec3 unshadowed = vec3(0.0);
  for (uint k = 0u; k < frame.environmentSamples; ++k) {
    EnvironmentPair pair = environment_pair(params, n, v, pixel, sample_index, frame.environmentSeed, k,
                                         frame.environmentSamples);
    uint slot = first + stride * k;
    if (with_environment) {
      vec4 e = sample_environment(pair.texel_bits, pair.environment_u);
      MisSample s = environment_technique_sample(params, n, v, from_map(e.xyz), e.w);
      environment_sample(slot, params, specular_scale, position, n, ng, v, s,
                         occlusion * environment_radiance(s.direction), unshadowed);
    }
    MisSample s = brdf_technique_sample(params, n, v, pair.brdf_direction, 0.0);
    vec3 incoming;
    if (ENVIRONMENT == 3) {
      uvec3 source = level_extent(0);
      float lod = filtered_sample_lod(s, frame.environmentSamples, int(source.y), int(source.z), int(frame.levelCount));
      vec4 filtered = filtered_lookup(s.direction, lod);
      incoming = filtered.rgb;
      if (with_environment) s.other_pdf = filtered.w;
    } else {
      s.other_pdf = environment_pdf(to_map(s.direction));
      incoming = environment_radiance(s.direction);
    }
    environment_sample(slot + stride - 1u, params, specular_scale, position, n, ng, v, s, occlusion * incoming,
                       unshadowed);
  }
  if (OCCLUSION == 0) write_unshadowed(first, unshadowed);
}

PunctualLight punctual_light(LightRecord record) {
  PunctualLight light;
  light.directional = record.type == FACET_LIGHT_DIRECTIONAL;
  light.spot = record.type == FACET_LIGHT_SPOT;
  light.position = vec3(record.positionX, record.positionY, record.positionZ);
  light.direction = vec3(record.directionX, record.directionY, record.directionZ);
  light.color = vec3(record.colorR, record.colorG, record.colorB);
  light.cos_inner = record.cosInner;
  light.cos_outer = record.cosOuter;
  return light;
}

void main() {
  uint index = invocation_index();
  bool continuation = PATHS == 1 && frame.pathVertex > 0u;
  if (index >= (continuation ? counters.pathRays : frame.pixelCount * frame.raysPerPixel)) return;
  uint camera = continuation ? pathRays[index].path : index;  // the camera ray: its slots and path
  uint sample_index = camera % frame.raysPerPixel;
  bool centre = !continuation && sample_index == 0u;
  bool shaded = is_shaded_sample(sample_index, frame.strata);
  uint pixel = camera / frame.raysPerPixel;
  HitRecord hit = hits[index];
  uint firstSlot = camera * frame.slotsPerRay;
  Ray ray = continuation ? to_ray(pathRays[index].ray) : camera_ray(index);
  vec3 direction = ray.direction;

  if (PATHS == 1 && hit.patchIndex == FACET_NO_HIT) pathStates[camera].alive = 0u;
  if (continuation && hit.patchIndex == FACET_NO_HIT) {
    // D at the vertex it left counted the environment, shadowed, over its
    // reflection lobes; its transmission lobe leads here only.
    if (TRANSMISSION == 1 && (pathStates[camera].flags & FACET_PATH_TRANSMITTED) != 0u) {
      for (uint slot = 0u; slot < frame.slotsPerRay; ++slot) write_unshadowed(firstSlot + slot, vec3(0.0));
      if (ENVIRONMENT != 0)
        write_unshadowed(firstSlot + uint(LIGHT_COUNT),
                         beer_lambert(path_medium(pathStates[camera]).sigma, INFINITE_DISTANCE) *
                             environment_radiance(direction));
    }
    return;
  }
  if (PATHS == 1 && hit.patchIndex != FACET_NO_HIT) atomicAdd(counters.pathHits, 1u);
  if (hit.patchIndex == FACET_NO_HIT) {
    if (centre) aovs[pixel] = PixelAovs(INFINITE_DISTANCE, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, FACET_NO_HIT,
                                        FACET_NO_HIT, 0.0, 0.0, 0.0, 0.0);
    for (uint slot = 0u; slot < frame.slotsPerRay; ++slot) write_unshadowed(firstSlot + slot, vec3(0.0));
    if (ENVIRONMENT != 0 && shaded) write_unshadowed(firstSlot + uint(LIGHT_COUNT), environment_radiance(direction));
    return;
  }

  vec3 origin = ray.origin;
  ObjectRange range = objects[hit.object];
  PatchRecord record = load_patch_record(hit.patchIndex);
  uvec4 header = texelFetch(patchHeaders, int(hit.patchIndex * FACET_HEADER_TEXELS));
  ControlPoints c = load_control_points(header[FACET_HEADER_FIRST_POINT], header[FACET_HEADER_KIND]);
  vec3 limit = limit_normal(c, hit.s, hit.tParam);
  vec3 n = shading_normal(record, hit.s, hit.tParam, limit);
  // A hit on a micro-triangle (the tessellated finish reports its normal)
  // lies on it; an exact hit is the limit point.
  vec3 triangleNormal = vec3(hit.geometricX, hit.geometricY, hit.geometricZ);
  bool onMicroTriangle = triangleNormal != vec3(0.0);
  vec3 position = onMicroTriangle ? origin + hit.t * direction : evaluate_patch(c, hit.s, hit.tParam).position;
  vec3 ng = onMicroTriangle ? triangleNormal : limit;
  // Two-sided: both normals face the eye.
  bool outside = !(dot(ng, direction) > 0.0);
  if (!outside) {
    n = -n;
    ng = -ng;
  }
  if (centre) {
    vec2 texcoord =
        surface_texcoord(channel_texel(record.firstTexcoord, range.channels, FACET_CHANNEL_TEXCOORD0), hit.s, hit.tParam)
            .uv;
    aovs[pixel] = PixelAovs(hit.t, position.x, position.y, position.z, ng.x, ng.y, ng.z, n.x, n.y, n.z,
                            range.patchIdOffset + record.sourcePatch, range.faceIdOffset + record.coarseFace,
                            record.faceU0 + hit.s * record.faceSize, record.faceV0 + hit.tParam * record.faceSize,
                            texcoord.x, texcoord.y);
  }

  BrdfParams params = brdf_params(range.material);
  if (CLEARCOAT == 1) params.clearcoat_normal = n;  // no normal map applies to the coat
  MaterialRecord m = materials[range.material];
  float occlusion = 1.0;
  vec3 emission = vec3(m.emissionR, m.emissionG, m.emissionB);
  vec2 anisotropyDirection = vec2(1.0, 0.0);
  if (TEXTURES == 1 && m.textured == 1u) {
    TexturedSurface surface = textured_hit(m, record, range.channels, c, hit, params, n, ng, direction);
    params = surface.params;
    n = surface.n;
    occlusion = surface.occlusion;
    emission = surface.emission;
    anisotropyDirection = surface.anisotropy_direction;
  }
  if (TRANSMISSION == 1 && m.transmissive == 1u) params = transmissive_brdf_params(params, transmission_params(m), outside);
  if (ANISOTROPY == 1 && params.anisotropy != 0.0) {
    PatchSample point = evaluate_patch(c, hit.s, hit.tParam);
    SurfaceTexcoord uv = surface_texcoord(channel_texel(record.firstTexcoord, range.channels, FACET_CHANNEL_TEXCOORD0),
                                          hit.s, hit.tParam);
    vec2 rotation = turned_rotation(vec2(m.anisotropyCos, m.anisotropySin), anisotropyDirection);
    params.tangent = texcoord_tangent(n, point.ds, point.dt, uv.ds, uv.dt, rotation.x, rotation.y);
  }
  vec3 v = -direction;
  // The coat lies over the emission too (KHR_materials_clearcoat).
  if (CLEARCOAT == 1 && params.clearcoat != 0.0) emission *= coat_transmittance(params, dot(params.clearcoat_normal, v));
  vec3 specular_scale = material_specular_scale(m.compensationTable, params, dot(n, v));
  for (int l = 0; l < LIGHT_COUNT; ++l) {
    LightIncidence incidence = light_incidence(punctual_light(lights[l]), position);
    if (shaded && light_arrives(incidence, n, ng))
      write_shadowed(firstSlot + l,
                     punctual_radiance(params, n, incidence.direction, v, incidence.color, specular_scale), position,
                     ng, incidence.direction, incidence.distance);
    else
      write_unshadowed(firstSlot + l, vec3(0.0));
  }
  if (ENVIRONMENT != 0) {
    // Every environment slot is written exactly once either way: the loops
    // of one invocation count against lavapipe's limit of 65535.
    uint first = firstSlot + uint(LIGHT_COUNT);
    if (shaded)
      shade_environment(first, frame.firstPixel + pixel, sample_index, range.material, params, specular_scale,
                        position, n, ng, v, occlusion);
    else
      for (uint slot = first; slot < firstSlot + frame.slotsPerRay; ++slot) write_unshadowed(slot, vec3(0.0));
  }
  if (EMISSION == 1) write_unshadowed(firstSlot + frame.slotsPerRay - 1u, shaded ? emission : vec3(0.0));
  if (PATHS == 1) {
    vec3 throughput = continuation ? path_throughput(pathStates[camera]) : vec3(1.0);
    PathMedium medium = PathMedium(range.material, 0u, vec3(0.0));
    if (TRANSMISSION == 1) {
      if (continuation) {
        medium.sigma = path_medium(pathStates[camera]).sigma;
        throughput *= beer_lambert(medium.sigma, length(position - origin));
      }
      medium.flags = (m.transmissive == 1u ? FACET_PATH_TRANSMISSIVE : 0u) | (outside ? FACET_PATH_OUTSIDE : 0u);
    }
    // Limits per lobe kind: the counts travel with the path (the camera ray's
    // vertex has taken none); without limits they stay 0, unread.
    uvec3 taken = LOBE_LIMITS == 1 && continuation ? path_lobes_taken(pathStates[camera]) : uvec3(0u);
    pathStates[camera] =
        pack_path_state(throughput, shaded, PathVertex(position, n, ng, v, params, specular_scale), medium, taken);
  }
}
