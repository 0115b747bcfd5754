// Hammersley's point set, the same on every run and on both backends.

#ifndef FACET_RULE_SAMPLING_LOW_DISCREPANCY
#define FACET_RULE_SAMPLING_LOW_DISCREPANCY

// The 32 bits of `bits` mirrored, by swapping halves, bytes, nibbles, pairs
// and bits. No loop, so a kernel's sample loop stays far from lavapipe's
// limit of 65535 iterations per invocation.
FACET_FN uint reverse_bits(uint bits) {
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  return ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
}

// Base-2 radical inverse of i >= 0 (van der Corput): its bits mirrored about
// the binary point.
FACET_FN real radical_inverse_base2(int i) { return real(reverse_bits(uint(i))) * real(2.3283064365386963e-10); }

// Point i of n: for n = 2^m a (0, m, 2)-net, one point in every elementary
// box of area 1/n. Both coordinates sit at the middle of their 1/n cells;
// the radical inverse alone starts at 0 and would bias every integral by
// half a cell.
FACET_FN vec2 hammersley_point(int i, int n) {
  real half_cell = real(0.5) / real(n);
  return vec2(real(i) / real(n) + half_cell, radical_inverse_base2(i) + half_cell);
}

#endif
