// The low-discrepancy points of Monte Carlo estimates (docs/rendering.md,
// "Samples"). The n points of one (pixel, camera sample) are a Hammersley net,
// each 2D group of dimensions shuffled and Owen-scrambled on its own (Burley
// 2020, "Practical Hash-based Owen Scrambling"), so that for n a power of 2
// they stratify every elementary box while pixels and groups stay independent.
// Integer arithmetic only: both backends draw the same bits.

#ifndef FACET_RULE_SAMPLING_SCRAMBLED_NET
#define FACET_RULE_SAMPLING_SCRAMBLED_NET

#include "rules/sampling/low_discrepancy.h"
#include "rules/sampling/random.h"

// A permutation of 32-bit words in which bit j of the result depends only on
// bits 0 ... j of x: reversed, it permutes each subinterval within its
// parent, Owen's nested scrambling (Laine & Karras 2011; the constants of
// Vegdahl 2021, "Building a Better LK Hash").
FACET_FN uint lower_bits_permutation(uint x, uint seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16u) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

FACET_FN uint owen_scramble(uint x, uint seed) { return reverse_bits(lower_bits_permutation(reverse_bits(x), seed)); }

// The smallest power of 2 at or above n >= 1.
FACET_FN uint power_of_two_at_least(uint n) {
  uint v = n - 1u;
  v |= v >> 1u;
  v |= v >> 2u;
  v |= v >> 4u;
  v |= v >> 8u;
  v |= v >> 16u;
  return v + 1u;
}

// Group `group` of point k of n (n <= 2^16) for (pixel, sample, seed): its
// two coordinates as 32-bit fractions. The points are a Hammersley net of
// m = n rounded up to a power of 2 (j/m, radical inverse of j), both
// coordinates Owen-scrambled, and j = k shuffled within [0, m) by the
// group's own permutation: without it, every group would scramble the same
// ordering and the groups' strata would stay correlated in a pixel, an
// error that no N removes.
FACET_FN uvec2 scrambled_point_bits(uint pixel, uint sample_index, uint seed, uint group, uint k, uint n) {
  uint key = pcg_hash(pixel ^ pcg_hash(sample_index ^ pcg_hash(seed * 16u + group)));
  uint m = power_of_two_at_least(n);
  uint j = lower_bits_permutation(k, pcg_hash(key + 1u)) & (m - 1u);
  uvec2 h = uvec2(j * (0xFFFFFFFFu / m + 1u), reverse_bits(j));
  return uvec2(owen_scramble(h.x, key), owen_scramble(h.y, pcg_hash(key)));
}

FACET_FN vec2 scrambled_point(uint pixel, uint sample_index, uint seed, uint group, uint k, uint n) {
  uvec2 b = scrambled_point_bits(pixel, sample_index, seed, group, k, n);
  return vec2(unit_from_bits(b.x), unit_from_bits(b.y));
}

#endif
