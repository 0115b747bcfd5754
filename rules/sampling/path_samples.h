// The random numbers of a path's vertices (docs/rendering.md, "Paths on the
// CPU reference"), drawn alike in float and double so that both backends can
// trace the same paths. Vertex 1, the camera ray's hit, keeps the numbers of a
// render without paths: its environment pairs are keyed by the scene's seed.
// Each later vertex keys its environment pairs by a seed of its own, and every
// vertex draws its continuation from a net keyed by a sample index no camera
// sample has, so no two vertices, and no vertex and its continuation, share
// numbers.

#ifndef FACET_RULE_SAMPLING_PATH_SAMPLES
#define FACET_RULE_SAMPLING_PATH_SAMPLES

#include "rules/sampling/random.h"
#include "rules/sampling/scrambled_net.h"

// Camera samples count up from 0 (at most 4097) and the camera's own net is
// keyed by 0xFFFFFFFF (camera_samples.h).
const uint PATH_CONTINUATION_SAMPLE = 0xFFFFFFFEu;

// The seed of vertex `vertex` (1 = the camera ray's hit) for its environment
// pairs and its continuation.
FACET_FN uint path_vertex_seed(uint seed, uint vertex) {
  if (vertex <= 1u) return seed;
  return pcg_hash(seed ^ pcg_hash(vertex + 0x9e3779b9u));
}

// The two numbers of the continuation direction that leaves vertex `vertex`
// (sample_brdf_lobes): point `sample_index` of a net of `samples` points over
// the pixel's camera samples, so that the pixel's continuations stratify.
FACET_FN vec2 path_continuation_u(uint pixel, uint sample_index, uint samples, uint seed, uint vertex) {
  return scrambled_point(pixel, PATH_CONTINUATION_SAMPLE, path_vertex_seed(seed, vertex), 0u, sample_index, samples);
}

// The number that decides whether the path survives Russian roulette at
// vertex `vertex`: the same point's next group.
FACET_FN real path_roulette_u(uint pixel, uint sample_index, uint samples, uint seed, uint vertex) {
  return scrambled_point(pixel, PATH_CONTINUATION_SAMPLE, path_vertex_seed(seed, vertex), 1u, sample_index, samples).x;
}

// Russian roulette from the third bounce on: a path survives with
// probability min(1, the largest channel of its throughput), and its
// throughput is divided by that probability (Arvo & Kirk 1990), so the
// estimate stays unbiased.
const uint PATH_FIRST_ROULETTE_BOUNCE = 3u;

FACET_FN real path_survival_probability(vec3 throughput, uint bounce) {
  if (bounce < PATH_FIRST_ROULETTE_BOUNCE) return real(1);
  return min(real(1), max(throughput.x, max(throughput.y, throughput.z)));
}

// The lobe kinds a path counts its continuations by, each against a limit of
// its own besides the bounces (render.diffuse_bounces, glossy_bounces,
// transmission_bounces; Cycles' defaults are 4, 4 and 12). A limit below 0
// is none: the bounces alone end the path.
const int PATH_LOBE_DIFFUSE = 0;
const int PATH_LOBE_GLOSSY = 1;
const int PATH_LOBE_TRANSMISSION = 2;

// Whether a path that has taken `taken` continuations of a lobe kind may take one more.
FACET_FN bool path_lobe_allowed(int taken, int limit) { return limit < 0 || taken < limit; }

// The number that picks reflection or transmission at a dielectric interface
// of vertex `vertex` (rules/shading/transmissive_continuation.h): the other
// coordinate of roulette's group.
FACET_FN real path_interface_u(uint pixel, uint sample_index, uint samples, uint seed, uint vertex) {
  return scrambled_point(pixel, PATH_CONTINUATION_SAMPLE, path_vertex_seed(seed, vertex), 1u, sample_index, samples).y;
}

#endif
