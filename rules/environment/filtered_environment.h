// The filtered method's estimator (docs/rendering.md, "Filtered importance
// sampling"). The sampled method's pairs and random numbers
// (sampled_environment.h), except that each BRDF sample reads the map's mip
// chain at the level its density asks for (Krivanek & Colbert 2008), so that
// few samples give a smooth estimate. Maps with a small bright source add the
// environment technique, the pair's other half, read at the map's own
// resolution and weighted by the power heuristic; on soft maps the BRDF samples
// alone have the lower error per unit time. A BRDF sample weighs itself against
// the environment's density filtered like its radiance (the density's own mip
// chain at the same level): against the point density, the sun's filtered halo
// around the sun, which no environment sample covers, would count in full.

#ifndef FACET_RULE_ENVIRONMENT_FILTERED_ENVIRONMENT
#define FACET_RULE_ENVIRONMENT_FILTERED_ENVIRONMENT

#include "rules/environment/prefilter.h"
#include "rules/environment/sampled_environment.h"

// A map whose brightest texel stands this far above its mean radiance
// (luminance, solid-angle weighted) has a source that filtered BRDF samples
// would smear and miss: the environment technique takes it.
const real FILTERED_MIS_DYNAMIC_RANGE = real(64);

FACET_FN bool filtered_uses_environment_samples(real largest_luminance, real mean_luminance) {
  return largest_luminance > FILTERED_MIS_DYNAMIC_RANGE * mean_luminance;
}

// The chain level a BRDF sample reads, one of `pairs`, on a map of
// width x height texels whose chain has `chain_levels` levels. Half a level
// finer than where a texel matches the sample's solid angle: a bilinear
// read already spreads over twice a texel's width, and its stratified
// neighbours (scrambled_net.h) cover the rest; chosen by measurement
// (docs/rendering.md, "Filtered importance sampling").
const real FILTERED_LOD_OFFSET = real(-0.5);

FACET_FN real filtered_sample_lod(MisSample s, uint pairs, int width, int height, int chain_levels) {
  return mip_level_for_density(s.pdf, int(pairs), width, height, chain_levels, FILTERED_LOD_OFFSET);
}

#endif
