// Beer-Lambert absorption inside a transmissive material
// (docs/shading.md, "Transmission").

#ifndef FACET_RULE_SHADING_ABSORPTION
#define FACET_RULE_SHADING_ABSORPTION

// glTF's KHR_materials_volume: light that travels attenuation_distance inside
// keeps attenuation_color of itself, so sigma = -ln(c) / d per channel; an
// infinite distance (or c = 1) absorbs nothing. A channel of c = 0 is taken
// at 1e-30, an absorption no render resolves from total.
FACET_FN vec3 absorption_coefficient(vec3 attenuation_color, real attenuation_distance) {
  vec3 c = max(attenuation_color, vec3(real(1.0e-30)));
  return -log(c) / attenuation_distance;
}

// exp(-sigma d) per channel; a channel with sigma = 0 transmits everything
// over any distance, infinite included.
FACET_FN vec3 beer_lambert(vec3 sigma, real distance) {
  vec3 t;
  t.x = sigma.x > real(0) ? exp(-sigma.x * distance) : real(1);
  t.y = sigma.y > real(0) ? exp(-sigma.y * distance) : real(1);
  t.z = sigma.z > real(0) ? exp(-sigma.z * distance) : real(1);
  return t;
}

// What a path keeps over its segment inside a medium of absorption sigma,
// from the vertex it left to the one it reached: measured between the two
// points, not from the ray's origin, which the leaving offset moved inside
// by an amount that grows with the scene's distance from the eye.
FACET_FN vec3 segment_transmittance(vec3 sigma, vec3 left, vec3 reached) {
  return beer_lambert(sigma, length(reached - left));
}

#endif
