// glTF's alphaMode MASK and BLEND: where a surface is present for a ray, by
// its alpha, the base colour factor's times its base colour texture's
// (docs/rendering.md, "Cutouts" and "Blending").

#ifndef FACET_RULE_SURFACE_CUTOUT
#define FACET_RULE_SURFACE_CUTOUT

#include "rules/sampling/random.h"
#include "rules/shading/textured_material.h"

// MASK: present where the alpha reaches the cutoff and absent elsewhere, for
// every ray. A cutoff of 0 keeps every hit: the surface is opaque.
FACET_FN bool cutout_present(real alpha_factor, real texture_alpha, real cutoff) {
  return alpha_factor * texture_alpha >= cutoff;
}

// Where a hit reads the cutout's texture: at texture coordinates `uv` and
// the finest level, because the hit is decided before a ray cone's
// footprint is known there (no partials: rules/texture/texture_sampling.h
// then reads level 0 with the magnification filter).
FACET_FN TextureFootprint cutout_footprint(vec2 uv) {
  TextureFootprint f;
  f.uv = uv;
  f.duv_ds = vec2(real(0));
  f.duv_dt = vec2(real(0));
  f.dp_ds = vec3(real(1), real(0), real(0));
  f.dp_dt = vec3(real(0), real(1), real(0));
  f.cone_width = real(0);
  f.cos_view = real(1);
  return f;
}

// BLEND, traced: present at a hit with probability alpha, for camera, shadow
// and continuation rays alike, so that over a pixel's samples the surface
// covers alpha of what lies behind it, passes 1 - alpha of a light's shadow
// rays and lets as many paths through. The number that decides is drawn from
// the ray's key and the (object, patch) it hits, not from the order in which
// a traversal meets its candidates, so both backends decide alike for the
// same ray; a ray that meets one patch twice decides once for both.
//
// A ray's key, from the numbers of the path vertex it belongs to
// (rules/sampling/path_samples.h): the camera or continuation ray that
// reaches the vertex whose numbers `vertex_seed` keys (slot
// PASS_THROUGH_NEAREST), or the shadow ray that leaves that vertex for `slot`
// of its camera ray's shadow slots (one per light, then the environment's).
const uint PASS_THROUGH_NEAREST = 0xFFFFFFFFu;

FACET_FN uint pass_through_key(uint pixel, uint sample_index, uint vertex_seed, uint slot) {
  return sample_bits(pixel, sample_index, pcg_hash(vertex_seed ^ 0x68bc21ebu) ^ pcg_hash(slot));
}

FACET_FN bool blend_present(real alpha, uint ray_key, uint object, uint patch_index) {
  return unit_from_bits(pcg_hash(ray_key ^ pcg_hash(patch_index ^ pcg_hash(object)))) < alpha;
}

#endif
