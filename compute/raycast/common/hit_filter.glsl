// Which hits a ray passes over, as if the surface were not there: a
// one-sided object's back faces (docs/rendering.md, "One-sided surfaces"),
// where a cutout's alpha is below its cutoff ("Cutouts") and where a blended
// surface lets the ray through ("Blending"), and near the transmissive
// surface a path's ray leaves ("Leaving a transmissive surface"). CULLING and
// CUTOUTS are 1 only where some object needs them, CUTOUTS 2 where some
// object blends, CROSSINGS 1 for continuation rays where some material
// transmits, so that other scenes run exactly the kernels they did; the
// object's flags are read only at a candidate hit. Included by trace_bindings.glsl, after scene_bindings.glsl.
#ifndef FACET_RAYCAST_HIT_FILTER_GLSL
#define FACET_RAYCAST_HIT_FILTER_GLSL

#include "rules/language.glsl"
#include "rules/surface/back_face.h"
#include "rules/surface/crossing.h"
#include "rules/surface/cutout.h"
#include "compute/raycast/common/patch_eval.glsl"
#include "compute/raycast/common/texcoord.glsl"
#include "compute/raycast/common/textures.glsl"
#include "compute/raycast/common/band_pixels.glsl"

layout(constant_id = 2) const int CULLING = 0;
layout(constant_id = 3) const int CUTOUTS = 0;
layout(constant_id = 4) const int CROSSINGS = 0;

// The key of the ray being traced (pass_through_key), which each kernel sets
// before it traces, where CUTOUTS is 2.
uint passThroughKey = 0u;

// The key of camera ray `camera` of the band, or of the continuation ray of
// its path: the numbers of the vertex the ray reaches (the frame's seed).
uint nearest_ray_key(uint camera) {
  return pass_through_key(image_pixel(camera / frame.raysPerPixel), camera % frame.raysPerPixel,
                          frame.environmentSeed, PASS_THROUGH_NEAREST);
}

// The key of the shadow ray of contribution slot `slot`: the numbers of the
// vertex it leaves (the frame's seed) and its place among its camera ray's
// slots.
uint shadow_ray_key(uint slot) {
  uint camera = slot / frame.slotsPerRay;
  return pass_through_key(image_pixel(camera / frame.raysPerPixel), camera % frame.raysPerPixel,
                          frame.environmentSeed, slot % frame.slotsPerRay);
}

// The transmissive surface the ray being traced leaves, which each kernel
// that traces continuation rays sets before it traces, where CROSSINGS is 1.
uint crossedObject = 0u;
SurfaceCrossing crossing = no_crossing();

void set_crossing(PathRayRecord ray) {
  crossedObject = ray.crossedObject;
  crossing.back = ray.crossingBack;
  crossing.inside = ray.crossingInside != 0u;
}

// Whether `object` passes over a hit at patch-local `st` of PatchRecord
// `patchIndex`, at `t` along a ray along `direction`, where the surface's
// geometric normal (of any length) is `normal`.
bool passes_over(uint object, vec3 direction, vec3 normal, uint patchIndex, vec2 st, float t) {
  if (CROSSINGS == 1 && crossing_passes_over(crossing, object == crossedObject, t, direction, normal)) return true;
  if (CULLING == 0 && CUTOUTS == 0) return false;
  uint flags = objects[object].flags;
  if (CULLING == 1 && (flags & FACET_OBJECT_CULL_BACK_FACES) != 0u && is_back_face(direction, normal)) return true;
  if (CUTOUTS == 0 || (flags & FACET_OBJECT_CUTOUT) == 0u) return false;
  ObjectRange o = objects[object];
  TextureSlotRecord slot = TextureSlotRecord(o.alphaTexture, o.alphaOffsetX, o.alphaOffsetY, o.alphaCosRotation,
                                             o.alphaSinRotation, o.alphaScaleX, o.alphaScaleY, o.alphaTexCoord);
  uint set = o.alphaTexCoord == 1u ? FACET_CHANNEL_TEXCOORD1 : FACET_CHANNEL_TEXCOORD0;
  PatchRecord record = load_patch_record(patchIndex);
  vec2 uv = surface_texcoord(channel_texel(record.firstTexcoord, o.channels, set), st.x, st.y).uv;
  float alpha = slot_value(slot, cutout_footprint(uv)).a;
  if (CUTOUTS == 2 && (flags & FACET_OBJECT_BLEND) != 0u)
    return !blend_present(o.alphaFactor * alpha, passThroughKey, object, record.sourcePatch);
  return !cutout_present(o.alphaFactor, alpha, o.alphaCutoff);
}

#endif
