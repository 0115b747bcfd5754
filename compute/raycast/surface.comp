// Per camera ray that hit: the surface point, its limit normal and, from the
// centre ray, the pixel's AOVs; per light of a shaded sample, the unshadowed
// radiance pi f(l, v) c_light (n.l) and the shadow ray that decides it
// (docs/rendering.md). Rays that miss only write the miss AOVs; a shadow ray
// the light model skips gets tMax = -1 and is not traced.
//
// Specialization: METHOD (0 exact, 1 tessellated), LIGHT_COUNT, and the
// BRDF models D_MODEL, G_MODEL, F_MODEL, each -1 when the scene's materials
// use several (the model is then read per material).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "compute/raycast/scene_bindings.glsl"
#include "materials/shading.glsl"

layout(constant_id = 0) const int METHOD = 0;
layout(constant_id = 1) const int LIGHT_COUNT = 1;
layout(constant_id = 2) const int D_MODEL = -1;
layout(constant_id = 3) const int G_MODEL = -1;
layout(constant_id = 4) const int F_MODEL = -1;

layout(set = 0, binding = 8, std430) readonly buffer Rays { RayRecord rays[]; };
layout(set = 0, binding = 9, std430) readonly buffer Hits { HitRecord hits[]; };
layout(set = 0, binding = 11, std430) readonly buffer Materials { MaterialRecord materials[]; };
layout(set = 0, binding = 12, std430) readonly buffer Lights { LightRecord lights[]; };
layout(set = 0, binding = 13, std430) writeonly buffer Aovs { PixelAovs aovs[]; };
layout(set = 0, binding = 14, std430) writeonly buffer ShadowRays { RayRecord shadowRays[]; };
layout(set = 0, binding = 15, std430) writeonly buffer Contributions { vec4 contributions[]; };
layout(set = 0, binding = 16, std430) buffer Counters { uint shadowRayCount; };

#include "compute/raycast/patch_eval.glsl"
#include "compute/raycast/limit_normal.glsl"

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
  uint firstShadow = index * uint(LIGHT_COUNT);

  if (hit.patchIndex == FACET_NO_HIT) {
    if (centre) aovs[pixel] = PixelAovs(infinity(), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, FACET_NO_HIT,
                                        FACET_NO_HIT, 0.0, 0.0);
    for (int l = 0; l < LIGHT_COUNT; ++l) {
      shadowRays[firstShadow + l] = RayRecord(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0);
      contributions[firstShadow + l] = vec4(0.0);
    }
    return;
  }

  RayRecord ray = rays[index];
  vec3 origin = vec3(ray.originX, ray.originY, ray.originZ);
  vec3 direction = vec3(ray.directionX, ray.directionY, ray.directionZ);
  ObjectRange range = objects[hit.object];
  PatchRecord record = patches[hit.patchIndex];
  ControlPoints c = load_control_points(range.firstPoint, record);
  vec3 n = limit_normal(c, hit.s, hit.tParam);
  // The exact method's hit point is the limit point; the tessellated one's
  // lies on the micro-triangle.
  vec3 position = METHOD == 0 ? evaluate_patch(c, hit.s, hit.tParam).position : origin + hit.t * direction;
  vec3 ng = METHOD == 0 ? n : vec3(hit.geometricX, hit.geometricY, hit.geometricZ);
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
  uint traced = 0u;
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
    vec3 shadowOrigin = position + frame.shadowOffset * ng;
    shadowRays[firstShadow + l] = RayRecord(shadowOrigin.x, shadowOrigin.y, shadowOrigin.z, frame.shadowOffset,
                                            toLight.x, toLight.y, toLight.z, lit ? distance : -1.0);
    contributions[firstShadow + l] =
        lit ? vec4(PI * brdf_evaluate(params, n, toLight, v) * cLight * nl, 0.0) : vec4(0.0);
    if (lit) ++traced;
  }
  if (traced > 0u) atomicAdd(shadowRayCount, traced);
}
