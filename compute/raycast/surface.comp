// Per camera ray that hit: the surface point, its limit normal and, from the
// centre ray, the pixel's AOVs; per light of a shaded sample, the unshadowed
// radiance pi f(l, v) c_light (n.l) and the shadow ray that decides it; then
// the environment's share (docs/rendering.md): prefiltered, or sampled
// without occlusion, in one slot that no ray tests; sampled with occlusion,
// one slot and shadow ray per environment and per BRDF sample. A ray that
// misses writes the miss AOVs and, with an environment, the radiance it
// sees in the environment's first slot. Every slot gets its contribution;
// the shadow rays that decide some of them are appended to one compacted
// list (counters.shadowRays), so the shadow pass costs nothing for slots,
// samples or pixels that need no ray.
//
// Specialization: LIGHT_COUNT, ENVIRONMENT
// (0 none, 1 sampled, 2 prefiltered), OCCLUSION (sampled: 1 traces the
// environment's shadow rays), and the BRDF models D_MODEL, G_MODEL,
// F_MODEL, each -1 when the scene's materials use several (the model is then
// read per material).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/scene_bindings.glsl"
#include "materials/shading.glsl"
#include "compute/shared/environment.h"
#include "compute/shared/random.h"

layout(constant_id = 1) const int LIGHT_COUNT = 1;
layout(constant_id = 2) const int D_MODEL = -1;
layout(constant_id = 3) const int G_MODEL = -1;
layout(constant_id = 4) const int F_MODEL = -1;
layout(constant_id = 5) const int ENVIRONMENT = 0;
layout(constant_id = 6) const int OCCLUSION = 1;

layout(set = 0, binding = 9, std430) readonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 11, std430) readonly buffer Materials { MaterialRecord materials[]; };
layout(set = 0, binding = 12, std430) readonly buffer Lights { LightRecord lights[]; };
layout(set = 0, binding = 13, std430) writeonly buffer Aovs { PixelAovs aovs[]; };
layout(set = 0, binding = 14, std430) writeonly buffer ShadowRays { ShadowRayRecord shadowRays[]; };
layout(set = 0, binding = 15, std430) writeonly buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 27) uniform samplerBuffer authoredNormals;
layout(set = 0, binding = 10, std430) buffer Counters { RenderCounters counters; };

#include "compute/raycast/patch_eval.glsl"
#include "compute/raycast/limit_normal.glsl"
#include "compute/raycast/environment.glsl"
#include "compute/raycast/ray.glsl"
#include "compute/raycast/camera_rays.glsl"
#include "compute/shared/authored_normal.h"

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

float infinity() { return uintBitsToFloat(0x7f800000u); }

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
  return p;
}

// A slot whose radiance arrives without a test.
void write_unshadowed(uint slot, vec3 radiance) { contributions[slot] = vec4(radiance, 0.0); }

// A slot whose radiance arrives unless something lies in [tMin, tMax)
// along the shadow ray; the shadow pass clears it then.
void write_shadowed(uint slot, vec3 radiance, vec3 origin, vec3 direction, float tMax) {
  contributions[slot] = vec4(radiance, 0.0);
  shadowRays[atomicAdd(counters.shadowRays, 1u)] = ShadowRayRecord(
      RayRecord(origin.x, origin.y, origin.z, frame.shadowOffset, direction.x, direction.y, direction.z, tMax), slot);
}

// Sampled method, one sample l of either technique (density `pdf`, the other
// technique's `other_pdf`): its MIS-weighted share, and with OCCLUSION its
// shadow ray for `slot`.
void environment_sample(uint slot, BrdfParams params, vec3 position, vec3 n, vec3 ng, vec3 v, vec3 l, float pdf,
                        float other_pdf, inout vec3 unshadowed) {
  float nl = dot(n, l);
  bool lit = pdf > 0.0 && nl > 0.0 && dot(ng, l) > 0.0;
  vec3 radiance = lit ? brdf_evaluate(params, n, l, v) * environment_radiance(l) * nl *
                            (power_heuristic(pdf, other_pdf) / pdf) / float(frame.environmentSamples)
                      : vec3(0.0);
  if (OCCLUSION == 0)
    unshadowed += radiance;
  else if (lit)
    write_shadowed(slot, radiance, position + frame.shadowOffset * ng, l, infinity());
  else
    write_unshadowed(slot, vec3(0.0));
}

// The environment's slots from `first` on.
void shade_environment(uint first, uint pixel, uint sample_index, uint material, BrdfParams params, vec3 position,
                       vec3 n, vec3 ng, vec3 v) {
  if (ENVIRONMENT == 2) {
    float nv = dot(n, v);
    if (nv <= COS_EPSILON) {  // nothing to look up (the lobe may not even exist)
      write_unshadowed(first, vec3(0.0));
      return;
    }
    vec3 lobe = split_sum_direction(n, v, params.alpha);
    vec3 radiance = split_sum(params, nv, prefiltered_radiance(to_map(lobe), params.alpha),
                              dfg_lookup(materials[material].dfgTable, nv, params.alpha),
                              irradiance_over_pi(to_map(n)));
    write_unshadowed(first, frame.environmentIntensity * radiance);
    return;
  }
  vec3 unshadowed = vec3(0.0);
  for (uint k = 0u; k < frame.environmentSamples; ++k) {
    uint d = ibl_dimension(frame.environmentSeed, k, 0u);
    vec4 e = sample_environment(sample_bits(pixel, sample_index, d),
                                vec3(sample_uniform(pixel, sample_index, d + 1u),
                                     sample_uniform(pixel, sample_index, d + 2u),
                                     sample_uniform(pixel, sample_index, d + 3u)));
    vec3 le = from_map(e.xyz);
    environment_sample(first + 2u * k, params, position, n, ng, v, le, e.w,
                                 brdf_lobes_pdf(params, n, le, v), unshadowed);
    vec3 ub = vec3(sample_uniform(pixel, sample_index, d + 4u), sample_uniform(pixel, sample_index, d + 5u),
                   sample_uniform(pixel, sample_index, d + 6u));
    vec3 lb = sample_brdf_lobes(params, n, v, ub);
    environment_sample(first + 2u * k + 1u, params, position, n, ng, v, lb,
                                 brdf_lobes_pdf(params, n, lb, v), environment_pdf(to_map(lb)), unshadowed);
  }
  if (OCCLUSION == 0) write_unshadowed(first, unshadowed);
}

// glTF's spot profile: a squared linear ramp in cos(theta) between the cones.
float spot_falloff(LightRecord light, vec3 fromLight) {
  float t = (dot(fromLight, vec3(light.directionX, light.directionY, light.directionZ)) - light.cosOuter) /
            max(light.cosInner - light.cosOuter, 1e-4);
  float ramp = clamp(t, 0.0, 1.0);
  return ramp * ramp;
}

void main() {
  uint index = invocation_index();
  if (index >= frame.pixelCount * frame.raysPerPixel) return;
  uint sample_index = index % frame.raysPerPixel;
  bool centre = sample_index == 0u;
  bool shaded = frame.raysPerPixel == 1u || sample_index > 0u;
  uint pixel = index / frame.raysPerPixel;
  HitRecord hit = hits[index];
  uint firstSlot = index * frame.slotsPerRay;
  Ray ray = camera_ray(index);
  vec3 direction = ray.direction;

  if (hit.patchIndex == FACET_NO_HIT) {
    if (centre) aovs[pixel] = PixelAovs(infinity(), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, FACET_NO_HIT,
                                        FACET_NO_HIT, 0.0, 0.0);
    for (uint slot = 0u; slot < frame.slotsPerRay; ++slot) write_unshadowed(firstSlot + slot, vec3(0.0));
    if (ENVIRONMENT != 0 && shaded) write_unshadowed(firstSlot + uint(LIGHT_COUNT), environment_radiance(direction));
    return;
  }

  vec3 origin = ray.origin;
  ObjectRange range = objects[hit.object];
  PatchRecord record = patches[hit.patchIndex];
  ControlPoints c = load_control_points(record.firstPoint, record.kind);
  vec3 limit = limit_normal(c, hit.s, hit.tParam);
  vec3 n = shading_normal(record, hit.s, hit.tParam, limit);
  // A hit on a micro-triangle (the tessellated finish reports its normal)
  // lies on it; an exact hit is the limit point.
  vec3 triangleNormal = vec3(hit.geometricX, hit.geometricY, hit.geometricZ);
  bool onMicroTriangle = triangleNormal != vec3(0.0);
  vec3 position = onMicroTriangle ? origin + hit.t * direction : evaluate_patch(c, hit.s, hit.tParam).position;
  vec3 ng = onMicroTriangle ? triangleNormal : limit;
  // Two-sided: both normals face the eye.
  if (dot(ng, direction) > 0.0) {
    n = -n;
    ng = -ng;
  }
  if (centre)
    aovs[pixel] = PixelAovs(hit.t, position.x, position.y, position.z, ng.x, ng.y, ng.z, n.x, n.y, n.z,
                            range.patchIdOffset + record.sourcePatch, range.faceIdOffset + record.coarseFace,
                            record.faceU0 + hit.s * record.faceSize, record.faceV0 + hit.tParam * record.faceSize);

  BrdfParams params = brdf_params(range.material);
  vec3 v = -direction;
  for (int l = 0; l < LIGHT_COUNT; ++l) {
    LightRecord light = lights[l];
    vec3 cLight = vec3(light.colorR, light.colorG, light.colorB);
    vec3 toLight;
    float distance = infinity();
    if (light.type == FACET_LIGHT_DIRECTIONAL) {
      toLight = -vec3(light.directionX, light.directionY, light.directionZ);
    } else {
      vec3 offset = vec3(light.positionX, light.positionY, light.positionZ) - position;
      distance = length(offset);
      toLight = offset / distance;
      cLight /= distance * distance;
      if (light.type == FACET_LIGHT_SPOT) cLight *= spot_falloff(light, -toLight);
    }
    float nl = dot(n, toLight);
    bool lit = shaded && nl > 0.0 && dot(ng, toLight) > 0.0 && cLight != vec3(0.0);
    if (lit)
      write_shadowed(firstSlot + l, PI * brdf_evaluate(params, n, toLight, v) * cLight * nl,
                     position + frame.shadowOffset * ng, toLight, distance);
    else
      write_unshadowed(firstSlot + l, vec3(0.0));
  }
  if (ENVIRONMENT != 0) {
    // Every environment slot is written exactly once either way: the loops
    // of one invocation count against lavapipe's limit of 65535.
    uint first = firstSlot + uint(LIGHT_COUNT);
    if (shaded)
      shade_environment(first, frame.firstPixel + pixel, sample_index, range.material, params, position,
                                  n, ng, v);
    else
      for (uint slot = first; slot < firstSlot + frame.slotsPerRay; ++slot) write_unshadowed(slot, vec3(0.0));
  }
}
