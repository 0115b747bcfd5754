// The limit normal dP/ds x dP/dt where that cross product vanishes
// (OpenSubdiv issues #947 and #1352). On our cages that happens at patch
// corners: where an infinitely sharp crease turns a corner, dP/ds and dP/dt
// become parallel; at some end-cap corners both are zero. The normal
// approaching such a point from inside its patch is well defined, so the
// surface is probed at points moved towards the patch centre by growing
// fractions of the way, and the first well-defined normal is taken. Each
// backend evaluates the probes with its own patch evaluation (the oracle
// rule of docs/architecture.md); this is what they decide alike.

#ifndef FACET_RULE_SURFACE_LIMIT_NORMAL
#define FACET_RULE_SURFACE_LIMIT_NORMAL

// The cross product is trusted when |ds x dt| exceeds this fraction of
// |ds| |dt| (the sine of the angle between them) and neither derivative is
// zero.
const real DEGENERATE_SINE = real(1.0e-6);
// Probes 0 .. LIMIT_NORMAL_PROBES - 1 move 1e-7, 1e-6, ... 1e-3 of the way.
const int LIMIT_NORMAL_PROBES = 5;

FACET_FN bool well_defined_normal(vec3 ds, vec3 dt, FACET_OUT(vec3) normal) {
  vec3 n = cross(ds, dt);
  real scale = length(ds) * length(dt);
  normal = vec3(real(0));
  if (!(scale > real(0)) || length(n) <= DEGENERATE_SINE * scale) return false;
  normal = normalize(n);
  return true;
}

// The fraction of the way probe `probe` moves, by repeated multiplication so
// that both backends step through the same values of their real type.
FACET_FN real limit_normal_probe_step(int probe) {
  real step = real(1.0e-7);
  for (int i = 0; i < probe; ++i) step *= real(10);
  return step;
}

FACET_FN real toward_patch_centre(real x, real centre, real step) { return x + step * (centre - x); }

// Degenerate across the whole neighbourhood (a collapsed patch): the
// normal at the patch centre is the best there is, and +z where even that
// vanishes.
FACET_FN vec3 unit_normal_or_up(vec3 n) {
  real size = length(n);
  return size > real(0) ? n / size : vec3(real(0), real(0), real(1));
}

#endif
