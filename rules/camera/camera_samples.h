// Where in its pixel each camera sample of sample_plan.h passes
// (docs/rendering.md, "Rays").
//
// Sample 0 passes through the pixel's centre. The shaded samples 1 ...
// strata^2 are the points of an Owen-scrambled net (scrambled_net.h) keyed
// by the pixel's index in the full image, so that a crop or a tile casts
// the rays of the whole render, by a sample index no camera sample has, so
// that they are independent of the lighting's nets, and by the scene's seed,
// so that renders with different seeds are independent in every dimension
// of a path (parity's paired t-test averages over them; docs/parity.md).

#ifndef FACET_RULE_CAMERA_CAMERA_SAMPLES
#define FACET_RULE_CAMERA_CAMERA_SAMPLES

#include "rules/camera/sample_plan.h"
#include "rules/sampling/scrambled_net.h"

const uint CAMERA_NET_SAMPLE = 0xFFFFFFFFu;

// In pixels from the pixel's corner.
FACET_FN vec2 sample_offset(uint pixel, uint sample_index, uint strata, uint seed) {
  if (sample_index == 0u) return vec2(real(0.5));
  return scrambled_point(pixel, CAMERA_NET_SAMPLE, seed, 0u, sample_index - 1u, shaded_sample_count(strata));
}

#endif
