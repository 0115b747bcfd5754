// Per ray that hit: the material at the hit (rules/shading/surface_at_hit.h),
// then one slot per light of its unshadowed radiance pi f c_light (n.l) with
// the shadow ray that decides it, the environment's share (docs/rendering.md:
// prefiltered in one slot no ray tests; sampled or filtered, one slot and
// shadow ray per sample of either technique), and emission. Shadow rays go to
// one compacted list (counters.shadowRays), so slots that need none cost
// none. A ray that misses writes the miss AOVs and the environment it sees.
// With PATHS (docs/rendering.md, "Paths") the invocations are a bounce's
// continuation rays past the camera rays', and each writes its path's state.
// Specialization: LIGHT_COUNT; the BRDF models D_MODEL, G_MODEL, F_MODEL (-1
// where the scene's materials use several: read per material); ENVIRONMENT
// (0 none, 1 sampled, 2 prefiltered, 3 filtered); FEATURES, the scene's
// features as bits (compute/layout/surface_features.h). With SHADOW_CATCHER
// (rules/shading/shadow_catcher.h) a camera ray passes over the catcher and
// a continuation finds it lit by the environment alone, its slots scaled to
// sum to the background behind it. With HOLDOUT a camera ray that hits a
// held-out object leaves its slots black and ends its path there.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/layout/surface_features.h"
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
#include "rules/shading/path_step.h"
#include "rules/shading/shadow_catcher.h"
#include "rules/shading/surface_at_hit.h"
#include "rules/shading/textured_material.h"
#include "rules/shading/transmissive_continuation.h"
#include "rules/surface/authored_normal.h"

layout(constant_id = 1) const int LIGHT_COUNT = 1;
layout(constant_id = 2) const int D_MODEL = -1;
layout(constant_id = 3) const int G_MODEL = -1;
layout(constant_id = 4) const int F_MODEL = -1;
layout(constant_id = 5) const int ENVIRONMENT = 0;
layout(constant_id = 6) const int FEATURES = 0;
const int OCCLUSION = (FEATURES >> FACET_FEATURE_OCCLUSION) & 1;
const int ENVIRONMENT_SAMPLES = (FEATURES >> FACET_FEATURE_ENVIRONMENT_SAMPLES) & 1;
const int TEXTURES = (FEATURES >> FACET_FEATURE_TEXTURES) & 1;
const int EMISSION = (FEATURES >> FACET_FEATURE_EMISSION) & 1;
const int COMPENSATION = (FEATURES >> FACET_FEATURE_COMPENSATION) & 1;
const int PATHS = (FEATURES >> FACET_FEATURE_PATHS) & 1;
const int TRANSMISSION = (FEATURES >> FACET_FEATURE_TRANSMISSION) & 1;
const int LOBE_LIMITS = (FEATURES >> FACET_FEATURE_LOBE_LIMITS) & 1;
const int ANISOTROPY = (FEATURES >> FACET_FEATURE_ANISOTROPY) & 1;
const int CLEARCOAT = (FEATURES >> FACET_FEATURE_CLEARCOAT) & 1;
const int SHEEN = (FEATURES >> FACET_FEATURE_SHEEN) & 1;
const int IRIDESCENCE = (FEATURES >> FACET_FEATURE_IRIDESCENCE) & 1;
const int CHANNELS = (FEATURES >> FACET_FEATURE_CHANNELS) & 1;
const int SHADOW_CATCHER = (FEATURES >> FACET_FEATURE_SHADOW_CATCHER) & 1;
const int HOLDOUT = (FEATURES >> FACET_FEATURE_HOLDOUT) & 1;

// Written only where a camera ray passes over a shadow catcher.
layout(set = 0, binding = 9, std430) buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 11, std430) readonly buffer Materials { MaterialRecord materials[]; };
layout(set = 0, binding = 12, std430) readonly buffer Lights { LightRecord lights[]; };
layout(set = 0, binding = 13, std430) writeonly buffer Aovs { PixelAovs aovs[]; };
layout(set = 0, binding = 14, std430) writeonly buffer ShadowRays { ShadowRayRecord shadowRays[]; };
// Read back only where a shadow catcher scales its environment slots.
layout(set = 0, binding = 15, std430) buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 27) uniform samplerBuffer authoredNormals;
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };
layout(set = 0, binding = 32, std430) buffer PathStates { PathState pathStates[]; };
layout(set = 0, binding = 33, std430) readonly buffer PathRays { PathRayRecord pathRays[]; };
layout(set = 0, binding = 34, std430) writeonly buffer LivePaths { uint livePaths[]; };

#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/shading/limit_normal.glsl"
#include "compute/raycast/common/texcoord.glsl"
#include "compute/raycast/shading/environment.glsl"
#include "compute/raycast/common/camera_rays.glsl"
#include "compute/raycast/common/textures.glsl"
#include "compute/raycast/shading/energy_compensation.glsl"
#include "compute/raycast/common/path_state.glsl"
#include "compute/raycast/shading/hit_material.glsl"

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

// What of a slot's radiance reaches the eye: for a camera ray that starts
// inside an absorbing solid, its segment's transmittance (camera_path_start);
// 1 otherwise. Applied as each slot is written, so that no loop walks the
// slots again (lavapipe ends an invocation's loops after 65535 iterations).
vec3 slotScale = vec3(1.0);

// A slot whose radiance arrives without a test.
void write_unshadowed(uint slot, vec3 radiance) { contributions[slot] = vec4(slotScale * radiance, 0.0); }

// A slot whose radiance arrives from `direction` unless something lies
// along the shadow ray from `position` up to tMax; the shadow pass clears it
// then.
void write_shadowed(uint slot, vec3 radiance, vec3 position, vec3 ng, vec3 direction, float tMax) {
  contributions[slot] = vec4(slotScale * radiance, 0.0);
  vec3 origin = shadow_ray_origin(position, ng, frame.shadowOffset);
  shadowRays[atomicAdd(counters.shadowRays, 1u)] = ShadowRayRecord(
      RayRecord(origin.x, origin.y, origin.z, frame.shadowOffset, direction.x, direction.y, direction.z, tMax), slot);
}

// Sampled or filtered method, one sample of either technique: its share for
// radiance `incoming`, added to `offered`, and with OCCLUSION its shadow ray
// for `slot`.
void environment_sample(uint slot, BrdfParams params, vec3 specular_scale, vec3 position, vec3 n, vec3 ng, vec3 v,
                        MisSample s, vec3 incoming, inout vec3 offered) {
  bool arrives = mis_sample_arrives(s, n, ng);
  vec3 radiance =
      arrives ? mis_sample_share(params, n, v, s, incoming, frame.environmentSamples, specular_scale) : vec3(0.0);
  offered += radiance;
  if (OCCLUSION == 0) return;
  if (arrives)
    write_shadowed(slot, radiance, position, ng, s.direction, INFINITE_DISTANCE);
  else
    write_unshadowed(slot, vec3(0.0));
}

// The environment's slots from `first` on, its light scaled by `occlusion`;
// returns what they hold before their shadow rays.
vec3 shade_environment(uint first, uint pixel, uint sample_index, uint material, BrdfParams params,
                       vec3 specular_scale, vec3 position, vec3 n, vec3 ng, vec3 v, float occlusion) {
  if (ENVIRONMENT == 2) {
    SplitSumLookups l = split_sum_lookups(params, n, v);
    if (!l.visible) {
      write_unshadowed(first, vec3(0.0));
      return vec3(0.0);
    }
    vec3 prefiltered = prefiltered_radiance(to_map(l.lobe), l.alpha);
    vec2 dfg = dfg_lookup(materials[material].dfgTable, l.nv, l.alpha);
    vec3 coat_prefiltered = vec3(0.0);
    vec2 coat_dfg = vec2(0.0);
    if (l.coated) {
      coat_prefiltered = prefiltered_radiance(to_map(l.coat_lobe), l.coat_alpha);
      coat_dfg = dfg_lookup(materials[material].coatDfgTable, l.nv_coat, l.coat_alpha);
    }
    vec3 radiance = environment_split_sum(params, l, prefiltered, dfg, irradiance_over_pi(to_map(n)), specular_scale,
                                          coat_prefiltered, coat_dfg);
    vec3 offered = occlusion * frame.environmentIntensity * radiance;
    write_unshadowed(first, offered);
    return offered;
  }
  // Per pair, the environment technique's slot (if drawn), then the BRDF technique's.
  bool with_environment = ENVIRONMENT == 1 || ENVIRONMENT_SAMPLES == 1;
  uint stride = with_environment ? 2u : 1u;
  vec3 offered = vec3(0.0);
  for (uint k = 0u; k < frame.environmentSamples; ++k) {
    EnvironmentPair pair = environment_pair(params, n, v, pixel, sample_index, frame.environmentSeed, k,
                                         frame.environmentSamples);
    uint slot = first + stride * k;
    if (with_environment) {
      vec4 e = sample_environment(pair.texel_bits, pair.environment_u);
      MisSample s = environment_technique_sample(params, n, v, from_map(e.xyz), e.w);
      environment_sample(slot, params, specular_scale, position, n, ng, v, s,
                         occlusion * environment_radiance(s.direction), offered);
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
                       offered);
  }
  if (OCCLUSION == 0) write_unshadowed(first, offered);
  return offered;
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

// A ray that hits nothing: the miss AOVs, and the environment it sees (a
// continuation only where it went through its last surface: D at the vertex
// it left counted the environment, shadowed, over its reflection lobes).
void shade_miss(uint camera, uint firstSlot, bool centre, bool shaded, bool continuation, vec3 direction) {
  if (continuation) {
    if (TRANSMISSION == 0 || (pathStates[camera].flags & FACET_PATH_TRANSMITTED) == 0u) return;
    for (uint slot = 0u; slot < frame.slotsPerRay; ++slot) write_unshadowed(firstSlot + slot, vec3(0.0));
    if (ENVIRONMENT != 0)
      write_unshadowed(firstSlot + uint(LIGHT_COUNT), beer_lambert(path_medium(pathStates[camera]).sigma,
                                                                   INFINITE_DISTANCE) *
                                                          environment_radiance(direction));
    return;
  }
  if (centre)
    aovs[camera / frame.raysPerPixel] = PixelAovs(INFINITE_DISTANCE, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                                                  FACET_NO_HIT, FACET_NO_HIT, 0.0, 0.0, 0.0, 0.0);
  for (uint slot = 0u; slot < frame.slotsPerRay; ++slot) write_unshadowed(firstSlot + slot, vec3(0.0));
  if (ENVIRONMENT != 0 && shaded) write_unshadowed(firstSlot + uint(LIGHT_COUNT), environment_radiance(direction));
}

void write_aovs(uint pixel, HitRecord hit, ObjectRange range, PatchRecord record, vec3 position, FacingNormals f) {
  vec2 texcoord =
      surface_texcoord(channel_texel(record.firstTexcoord, range.channels, FACET_CHANNEL_TEXCOORD0), hit.s, hit.tParam)
          .uv;
  aovs[pixel] = PixelAovs(hit.t, position.x, position.y, position.z, f.ng.x, f.ng.y, f.ng.z, f.n.x, f.n.y, f.n.z,
                          range.patchIdOffset + record.sourcePatch, range.faceIdOffset + record.coarseFace,
                          record.faceU0 + hit.s * record.faceSize, record.faceV0 + hit.tParam * record.faceSize,
                          texcoord.x, texcoord.y);
}

// Each light's slot from `first` on: its unshadowed radiance and the shadow
// ray that decides it.
void shade_lights(uint first, bool shaded, SurfaceAtHit s, vec3 position, vec3 v, vec3 specular_scale) {
  for (int l = 0; l < LIGHT_COUNT; ++l) {
    LightIncidence incidence = light_incidence(punctual_light(lights[l]), position);
    if (shaded && light_arrives(incidence, s.n, s.ng))
      write_shadowed(first + l, punctual_radiance(s.params, s.n, incidence.direction, v, incidence.color, specular_scale),
                     position, s.ng, incidence.direction, incidence.distance);
    else
      write_unshadowed(first + l, vec3(0.0));
  }
}

// The camera ray's path moves on to this vertex: a continuation's segment
// takes Beer-Lambert's factor of the medium it crossed, a camera ray's path
// starts as `start` says; the counts per lobe kind travel with the path (the
// camera ray's vertex has taken none). A shaded vertex puts its path on the
// live list, which the next bounce continues.
void store_path_state(uint camera, bool continuation, bool shaded, PathVertex x, uint object, uint material,
                      PathCarry start) {
  vec3 throughput = continuation ? path_throughput(pathStates[camera]) : start.throughput;
  PathMedium medium = PathMedium(object, material, 0u, x.transmission.transmission, start.sigma);
  if (TRANSMISSION == 1) {
    if (continuation) {
      medium.sigma = path_medium(pathStates[camera]).sigma;
      PathState left = pathStates[camera];
      throughput *= segment_transmittance(medium.sigma, vec3(left.positionX, left.positionY, left.positionZ), x.position);
    }
    medium.flags = (x.transmissive ? FACET_PATH_TRANSMISSIVE : 0u) | (x.outside ? FACET_PATH_OUTSIDE : 0u);
  }
  uvec3 taken = LOBE_LIMITS == 1 && continuation ? path_lobes_taken(pathStates[camera]) : uvec3(0u);
  pathStates[camera] = pack_path_state(throughput, x, medium, taken);
  if (shaded) livePaths[atomicAdd(counters.livePaths, 1u)] = camera;
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
  vec3 direction = ray.direction, v = -direction;
  if (SHADOW_CATCHER == 1 && hit.patchIndex != FACET_NO_HIT && !catcher_seen_at(frame.pathVertex + 1u) &&
      (objects[hit.object].flags & FACET_OBJECT_SHADOW_CATCHER) != 0u) {
    // The camera ray passes over the catcher; gather reads a miss.
    hits[index].patchIndex = FACET_NO_HIT;
    hit.patchIndex = FACET_NO_HIT;
  }
  if (hit.patchIndex == FACET_NO_HIT) {
    shade_miss(camera, firstSlot, centre, shaded, continuation, direction);
    return;
  }
  if (PATHS == 1) atomicAdd(counters.pathHits, 1u);

  ObjectRange range = objects[hit.object];
  bool catcher = SHADOW_CATCHER == 1 && (range.flags & FACET_OBJECT_SHADOW_CATCHER) != 0u;
  if (HOLDOUT == 1 && !continuation && (range.flags & FACET_OBJECT_HOLDOUT) != 0u) shaded = false;
  PatchRecord record = load_patch_record(hit.patchIndex);
  uvec4 header = texelFetch(patchHeaders, int(hit.patchIndex * FACET_HEADER_TEXELS));
  ControlPoints c = load_control_points(header[FACET_HEADER_FIRST_POINT], header[FACET_HEADER_KIND]);
  vec3 limit = limit_normal(c, hit.s, hit.tParam);
  // A hit on a micro-triangle (the tessellated finish reports its normal)
  // lies on it; an exact hit is the limit point.
  vec3 triangleNormal = vec3(hit.geometricX, hit.geometricY, hit.geometricZ);
  bool onMicroTriangle = triangleNormal != vec3(0.0);
  vec3 position = onMicroTriangle ? ray.origin + hit.t * direction : evaluate_patch(c, hit.s, hit.tParam).position;
  FacingNormals facing = facing_normals(shading_normal(record, hit.s, hit.tParam, limit),
                                        onMicroTriangle ? triangleNormal : limit, v);
  if (centre) write_aovs(pixel, hit, range, record, position, facing);
  PathCarry start = PathCarry(vec3(1.0), vec3(0.0), uvec3(0u));
  vec3 eyeSigma = vec3(frame.eyeSigmaR, frame.eyeSigmaG, frame.eyeSigmaB);
  if (TRANSMISSION == 1 && !continuation && eyeSigma != vec3(0.0)) {
    // The eye inside an absorbing solid sees this vertex through it.
    start = camera_path_start(eyeSigma, vec3(0.0), position);
    slotScale = start.throughput;
  }

  MaterialRecord m = materials[range.material];
  bool anisotropic = ANISOTROPY == 1 && m.anisotropy != 0.0;
  PatchSample p;
  if ((TEXTURES == 1 && m.textured == 1u) || anisotropic) p = evaluate_patch(c, hit.s, hit.tParam);
  SurfaceAtHit s = surface_at_hit(hit_material(m, record, range.channels, p, hit, facing.ng, direction), facing, v,
                                  hit_partials(anisotropic, range, record, p, hit));
  // The catcher is lit by the environment alone, whose share it measures.
  vec3 background = catcher && ENVIRONMENT != 0 ? environment_radiance(direction) : vec3(0.0);
  vec3 specular_scale = material_specular_scale(m.compensationTable, s.params, dot(s.n, v),
                                                TRANSMISSION == 1 && m.transmissive == 1u, s.outside);
  shade_lights(firstSlot, shaded && !catcher, s, position, v, specular_scale);
  vec3 offered = vec3(0.0);
  if (ENVIRONMENT != 0) {
    // Every environment slot is written exactly once either way: the loops
    // of one invocation count against lavapipe's limit of 65535.
    uint first = firstSlot + uint(LIGHT_COUNT);
    bool sealedOff = TRANSMISSION == 1 && ENVIRONMENT != 2 && OCCLUSION == 1 &&
                     environment_sealed_off(m.transmissive == 1u, s.transmission, s.outside,
                                            (range.flags & FACET_OBJECT_SEALED) != 0u);
    if (shaded && !sealedOff)
      offered = shade_environment(first, image_pixel(pixel), sample_index, range.material, s.params, specular_scale,
                                  position, s.n, s.ng, v, s.occlusion);
    else
      for (uint slot = first; slot < firstSlot + frame.slotsPerRay; ++slot) write_unshadowed(slot, vec3(0.0));
  }
  vec3 emitted = s.emission;
  if (catcher) {
    vec3 scale = catcher_slot_scale(background, offered);
    for (uint slot = firstSlot + uint(LIGHT_COUNT); slot < firstSlot + frame.slotsPerRay - 1u; ++slot)
      contributions[slot].xyz *= scale;
    emitted = catcher_unshadowed(background, offered);
    s.params = catcher_path_params(s.params);
  }
  if (EMISSION == 1) write_unshadowed(firstSlot + frame.slotsPerRay - 1u, shaded ? emitted : vec3(0.0));
  if (PATHS == 1)
    store_path_state(camera, continuation, shaded,
                     PathVertex(position, s.n, s.ng, v, s.params, specular_scale,
                                TRANSMISSION == 1 && m.transmissive == 1u, s.transmission, s.outside),
                     hit.object, range.material, start);
}
