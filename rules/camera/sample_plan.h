// Which camera rays a pixel casts and how they make its beauty
// (docs/rendering.md, "Rays").
//
// spp = strata^2. Sample 0 is the ray through the pixel's centre: it gives
// the AOVs, and at 1 spp the beauty. Above 1 spp samples 1 ... strata^2 are
// the points of a scrambled net over the pixel (camera_samples.h), and only
// they are shaded. The beauty is the mean of the shaded samples (misses
// count as black); alpha is the fraction of them that hit.

#ifndef FACET_RULE_CAMERA_SAMPLE_PLAN
#define FACET_RULE_CAMERA_SAMPLE_PLAN

FACET_FN uint sample_strata(uint samples_per_pixel) {
  return uint(floor(sqrt(real(samples_per_pixel)) + real(0.5)));
}

FACET_FN uint rays_per_pixel(uint strata) { return strata == 1u ? 1u : strata * strata + 1u; }

FACET_FN uint first_shaded_sample(uint strata) { return strata == 1u ? 0u : 1u; }

FACET_FN bool is_shaded_sample(uint sample_index, uint strata) { return sample_index >= first_shaded_sample(strata); }

FACET_FN uint shaded_sample_count(uint strata) { return strata * strata; }

#endif
