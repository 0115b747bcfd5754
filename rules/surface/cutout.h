// glTF's alphaMode MASK: a surface is present where its alpha, the base
// colour factor's times its base colour texture's, reaches the cutoff, and
// absent elsewhere, for every ray (docs/rendering.md, "Cutouts"). A cutoff
// of 0 keeps every hit: the surface is opaque.

#ifndef FACET_RULE_SURFACE_CUTOUT
#define FACET_RULE_SURFACE_CUTOUT

#include "rules/shading/textured_material.h"

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

#endif
