// The random numbers of Monte Carlo estimates, drawn as a pure function of
// (pixel, sample, dimension) so that the GPU kernels and the CPU reference draw
// exactly the same ones, in any order.

#ifndef FACET_RULE_SAMPLING_RANDOM
#define FACET_RULE_SAMPLING_RANDOM

// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
FACET_FN uint pcg_hash(uint value) {
  uint state = value * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// The 32 random bits of (pixel, sample, dimension).
FACET_FN uint sample_bits(uint pixel, uint sample_index, uint dimension) {
  return pcg_hash(pixel ^ pcg_hash(sample_index ^ pcg_hash(dimension)));
}

// A number in [0, 1) from the top 24 of 32 bits: exact in float and in
// double, so both backends start from the same value.
FACET_FN real unit_from_bits(uint bits) { return real(bits >> 8u) * real(5.9604644775390625e-8); }

FACET_FN real sample_uniform(uint pixel, uint sample_index, uint dimension) {
  return unit_from_bits(sample_bits(pixel, sample_index, dimension));
}

#endif
