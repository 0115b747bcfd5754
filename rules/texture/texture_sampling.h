// How a texture is read, short of the texel fetch itself, which each backend
// does from its own storage (docs/shading.md, "Textures"). Addressing and
// filtering follow the glTF 2.0 sampler (OpenGL's rules: texel centres at
// half-integers, the mip level from the footprint); the level of detail comes
// from a ray cone (Akenine-Möller et al., "Improved Shader and Texture Level of
// Detail Using Ray Cones", JCGT 2021).

#ifndef FACET_RULE_TEXTURE_TEXTURE_SAMPLING
#define FACET_RULE_TEXTURE_TEXTURE_SAMPLING

// Texture coordinate wrap modes (glTF sampler wrapS / wrapT).
const uint FACET_WRAP_REPEAT = 0u;
const uint FACET_WRAP_MIRRORED_REPEAT = 1u;
const uint FACET_WRAP_CLAMP_TO_EDGE = 2u;

// Texel filters (magFilter, and minFilter within a level) and the mip modes
// of minFilter: none reads level 0, nearest the closest level, linear
// blends the two around the level of detail.
const uint FACET_FILTER_NEAREST = 0u;
const uint FACET_FILTER_LINEAR = 1u;
const uint FACET_MIP_NONE = 0u;
const uint FACET_MIP_NEAREST = 1u;
const uint FACET_MIP_LINEAR = 2u;

// The integer texel `i` of a level `size` texels wide, wrapped into [0, size).
FACET_FN int wrap_texel(int i, int size, uint mode) {
  if (mode == FACET_WRAP_CLAMP_TO_EDGE) return clamp(i, 0, size - 1);
  int period = mode == FACET_WRAP_MIRRORED_REPEAT ? 2 * size : size;
  int r = i - period * int(floor(real(i) / real(period)));
  return r < size ? r : period - 1 - r;
}

// The texels one lookup reads in a level, and the weights of the second
// column and row: a nearest lookup reads (x0, y0) alone (fx = fy = 0).
struct TexelTaps {
  int x0;
  int y0;
  int x1;
  int y1;
  real fx;
  real fy;
};

// Texture coordinates `uv` (0 to 1 across the level, v down the rows as glTF
// stores images) in a level of width x height texels.
FACET_FN TexelTaps texel_taps(vec2 uv, int width, int height, uint texel_filter, uint wrap_s, uint wrap_t) {
  // Coordinates beyond 2^24 texels (or NaN) read texel 0: their integer
  // parts would not survive the conversion to int.
  real x = uv.x * real(width);
  real y = uv.y * real(height);
  x = abs(x) < real(16777216) ? x : real(0);
  y = abs(y) < real(16777216) ? y : real(0);
  TexelTaps taps;
  if (texel_filter == FACET_FILTER_NEAREST) {
    taps.x0 = wrap_texel(int(floor(x)), width, wrap_s);
    taps.y0 = wrap_texel(int(floor(y)), height, wrap_t);
    taps.x1 = taps.x0;
    taps.y1 = taps.y0;
    taps.fx = real(0);
    taps.fy = real(0);
    return taps;
  }
  real fx = floor(x - real(0.5));
  real fy = floor(y - real(0.5));
  taps.x0 = wrap_texel(int(fx), width, wrap_s);
  taps.y0 = wrap_texel(int(fy), height, wrap_t);
  taps.x1 = wrap_texel(int(fx) + 1, width, wrap_s);
  taps.y1 = wrap_texel(int(fy) + 1, height, wrap_t);
  taps.fx = x - real(0.5) - fx;
  taps.fy = y - real(0.5) - fy;
  return taps;
}

// The levels one lookup reads and the weight of the second: magnified
// (lod <= 0) or without mips, level 0 with the magnification or the
// minification filter.
struct MipTaps {
  int level0;
  int level1;
  real blend;
  uint texel_filter;
};

FACET_FN MipTaps mip_taps(real lod, int levels, uint mag_filter, uint min_filter, uint mip_mode) {
  MipTaps taps;
  taps.level0 = 0;
  taps.level1 = 0;
  taps.blend = real(0);
  taps.texel_filter = lod <= real(0) ? mag_filter : min_filter;
  if (lod <= real(0) || mip_mode == FACET_MIP_NONE) return taps;
  real top = real(levels - 1);
  real l = lod < top ? lod : top;  // NaN reads the coarsest level
  if (mip_mode == FACET_MIP_NEAREST) {
    // OpenGL's rounding: the level nearest to lod, halves rounding down.
    taps.level0 = int(ceil(l + real(0.5)) - real(1));
    taps.level1 = taps.level0;
    return taps;
  }
  taps.level0 = int(floor(l));
  taps.level1 = min(taps.level0 + 1, levels - 1);
  taps.blend = l - real(taps.level0);
  return taps;
}

// The texture level of detail of a ray cone of width `cone_width` at a hit
// whose direction meets the shading normal at cos_view = |n.d|, on a surface
// point with position partials dp_ds, dp_dt and texture coordinate partials
// duv_ds, duv_dt over a texture of width x height texels at level 0
// (Akenine-Möller et al. 2021, eq. 34: texel area over surface area, then
// the cone's footprint); -64 where the coordinates do not vary.
FACET_FN real cone_texture_lod(real cone_width, real cos_view, vec3 dp_ds, vec3 dp_dt, vec2 duv_ds, vec2 duv_dt,
                               int width, int height) {
  vec3 surface = cross(dp_ds, dp_dt);
  real surface_area = sqrt(dot(surface, surface));
  real texel_area = abs(duv_ds.x * duv_dt.y - duv_ds.y * duv_dt.x) * real(width) * real(height);
  real footprint = cone_width / max(cos_view, real(1.0e-4));
  real texels = footprint * sqrt(texel_area / max(surface_area, real(1.0e-30)));
  // log2(x) as log(x) / ln 2: C++ and GLSL share log, not log2.
  return texels > real(0) ? real(1.44269504088896340736) * log(texels) : real(-64);
}

// KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv with the
// extension's matrices, the rotation given as its cosine and sine.
FACET_FN vec2 transform_uv(vec2 uv, vec2 offset, real cos_rotation, real sin_rotation, vec2 scale) {
  vec2 s = vec2(uv.x * scale.x, uv.y * scale.y);
  return vec2(cos_rotation * s.x + sin_rotation * s.y, cos_rotation * s.y - sin_rotation * s.x) + offset;
}

// The linear value of an sRGB-encoded channel in [0, 1] (IEC 61966-2-1).
FACET_FN real srgb_to_linear(real c) {
  return c <= real(0.04045) ? c / real(12.92) : pow((c + real(0.055)) / real(1.055), real(2.4));
}

#endif
