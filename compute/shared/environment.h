// Shared GLSL / C++ source (the rules of materials/shading/common.h: scalar
// type `real`, typed literals, no references): the environment's geometry
// and the pieces of image-based lighting both backends compute the same way.
// C++ instantiates it in engine/ibl/environment_math.h; kernels include it
// after materials/shading.glsl. No include guard (C++ includes it once per
// real type).
//
// Equirectangular mapping, for a direction d in the map's frame:
//   u = 1/2 + atan2(d.x, -d.z) / (2 pi)   (u = 1/2 looks down -z)
//   v = acos(d.y) / pi                      (v = 0 is +y, row 0 of the map)
// Texel (x, y) of a W x H map covers u in [x, x+1] / W, v in [y, y+1] / H;
// its solid angle is (2 pi / W)(cos(pi y / H) - cos(pi (y+1) / H)), and the
// solid angles of all texels sum to 4 pi exactly (up to rounding).

// World direction -> map frame: the map is turned by `rotation` (given as
// its cosine and sine) about +y, so the world sees R d_map; undo it.
FACET_FN vec3 environment_to_map(vec3 d, real cos_rotation, real sin_rotation) {
  return vec3(cos_rotation * d.x - sin_rotation * d.z, d.y, sin_rotation * d.x + cos_rotation * d.z);
}

FACET_FN vec3 environment_from_map(vec3 d, real cos_rotation, real sin_rotation) {
  return vec3(cos_rotation * d.x + sin_rotation * d.z, d.y, -sin_rotation * d.x + cos_rotation * d.z);
}

// theta from atan2 rather than acos(d.y): well conditioned at the poles,
// and lavapipe's acos is far less accurate than its atan.
FACET_FN vec2 environment_uv(vec3 d) {
  real u = real(0.5) + atan(d.x, -d.z) * (real(0.5) * INV_PI);
  real v = atan(sqrt(d.x * d.x + d.z * d.z), d.y) * INV_PI;
  return vec2(u, v);
}

FACET_FN vec3 environment_direction(vec2 uv) {
  real phi = real(2) * PI * (uv.x - real(0.5));
  real cos_theta = cos(PI * uv.y);
  real sin_theta = sin(PI * uv.y);
  return vec3(sin_theta * sin(phi), cos_theta, -sin_theta * cos(phi));
}

// The direction with polar cosine `cos_theta` at longitude u (sampling
// draws cos theta uniformly within a row, so the density is constant per
// unit solid angle inside each texel).
FACET_FN vec3 environment_direction_cos(real u, real cos_theta) {
  real phi = real(2) * PI * (u - real(0.5));
  real sin_theta = sqrt(max(real(1) - cos_theta * cos_theta, real(0)));
  return vec3(sin_theta * sin(phi), cos_theta, -sin_theta * cos(phi));
}

FACET_FN real environment_row_cos(int y, int height) { return cos(PI * real(y) / real(height)); }

FACET_FN real environment_texel_solid_angle(int y, int width, int height) {
  return real(2) * PI / real(width) * (environment_row_cos(y, height) - environment_row_cos(y + 1, height));
}

FACET_FN real luminance(vec3 c) { return real(0.2126) * c.x + real(0.7152) * c.y + real(0.0722) * c.z; }

// Bilinear footprint of a lookup at uv: texel columns x0, x1 (wrapping),
// rows y0, y1 (clamped at the poles) and the weights of x1 and y1.
struct BilinearTaps {
  int x0;
  int x1;
  int y0;
  int y1;
  real fx;
  real fy;
};

FACET_FN BilinearTaps environment_bilinear(vec2 uv, int width, int height) {
  real x = uv.x * real(width) - real(0.5);
  real y = clamp(uv.y * real(height) - real(0.5), real(0), real(height - 1));
  real xf = floor(x);
  real yf = floor(y);
  BilinearTaps b;
  b.fx = x - xf;
  b.fy = y - yf;
  int xi = int(xf);  // >= -1: uv.x >= 0
  b.x0 = xi < 0 ? xi + width : xi % width;
  b.x1 = (b.x0 + 1) % width;
  b.y0 = int(yf);
  b.y1 = min(b.y0 + 1, height - 1);
  return b;
}

// Multiple importance sampling, one sample from each of two techniques:
// Veach's power heuristic (beta = 2) for the technique of density `pdf`.
FACET_FN real power_heuristic(real pdf, real other_pdf) {
  real a = pdf * pdf;
  real b = other_pdf * other_pdf;
  return a + b > real(0) ? a / (a + b) : real(0);
}

// Probability of choosing the specular lobe when sampling the BRDF: the
// share of the lobes' albedo at normal incidence, kept within [0.1, 0.9]
// when both are present so that neither lobe is starved.
FACET_FN real specular_lobe_probability(BrdfParams p) {
  real specular = luminance(fresnel_F(p, real(1)));
  real diffuse = luminance(p.diffuse);
  if (diffuse <= real(0)) return real(1);
  if (specular <= real(0)) return real(0);
  return clamp(specular / (specular + diffuse), real(0.1), real(0.9));
}

// The microfacet technique a material samples its specular lobe with: GGX's
// visible normals where D is GGX, else D-proportional normals.
FACET_FN int specular_technique(BrdfParams p) { return p.d_model == D_GGX ? SAMPLE_GGX_VISIBLE : SAMPLE_D; }

// One BRDF sample: u.x picks the lobe, u.yz the direction within it.
FACET_FN vec3 sample_brdf_lobes(BrdfParams p, vec3 n, vec3 v, vec3 u) {
  real p_spec = specular_lobe_probability(p);
  vec2 uv = vec2(u.y, u.z);
  return u.x < p_spec ? sample_direction(specular_technique(p), p, n, v, uv)
                      : sample_direction(SAMPLE_COSINE, p, n, v, uv);
}

FACET_FN real brdf_lobes_pdf(BrdfParams p, vec3 n, vec3 l, vec3 v) {
  real p_spec = specular_lobe_probability(p);
  real pdf = real(0);
  if (p_spec > real(0)) pdf += p_spec * direction_pdf(specular_technique(p), p, n, l, v);
  if (p_spec < real(1)) pdf += (real(1) - p_spec) * direction_pdf(SAMPLE_COSINE, p, n, l, v);
  return pdf;
}

// Split sum, specular part (Karis 2013): the prefiltered map is sampled at
// perceptual roughness sqrt(alpha) on levels spaced evenly in it; level i of
// `levels` has alpha = (i / (levels - 1))^2, level 0 is the map itself.
FACET_FN real prefiltered_level(real alpha, int levels) {
  return sqrt(clamp(alpha, real(0), real(1))) * real(levels - 1);
}

FACET_FN real prefiltered_level_alpha(int level, int levels) { return sqr(real(level) / real(levels - 1)); }

// The DFG table's two integrals for one sample l of the specular lobe
// (F = 1), weighted by n.l / pdf: scale multiplies F(0), bias is added, so
// that F(0) scale + bias = integral of f_spec (n.l) for Schlick's F.
FACET_FN vec2 dfg_sample_weight(real specular_value, real nl, real pdf, real vh) {
  if (pdf <= real(0) || nl <= real(0)) return vec2(real(0));
  real w = specular_value * nl / pdf;
  real fc = pow(real(1) - clamp(vh, real(0), real(1)), real(5));
  return vec2(w * (real(1) - fc), w * fc);
}

// Spherical harmonics, bands 0-2, real basis, evaluated at unit d.
FACET_FN real sh_basis(int i, vec3 d) {
  switch (i) {
    case 0:
      return real(0.282094791773878);
    case 1:
      return real(0.488602511902920) * d.y;
    case 2:
      return real(0.488602511902920) * d.z;
    case 3:
      return real(0.488602511902920) * d.x;
    case 4:
      return real(1.092548430592079) * d.x * d.y;
    case 5:
      return real(1.092548430592079) * d.y * d.z;
    case 6:
      return real(0.315391565252520) * (real(3) * d.z * d.z - real(1));
    case 7:
      return real(1.092548430592079) * d.x * d.z;
    case 8:
      return real(0.546274215296340) * (d.x * d.x - d.y * d.y);
  }
  return real(0);
}

// Ramamoorthi & Hanrahan 2001: convolving radiance with the clamped cosine
// scales band l by A_l; divided by pi here so that the result times c_diff is
// the Lambertian radiance c_diff / pi x irradiance.
FACET_FN real sh_cosine_band(int i) {
  if (i == 0) return real(1);
  if (i < 4) return real(2) / real(3);
  return real(0.25);
}

// Where the split sum reads the prefiltered map. The levels were filtered
// with v = n = r; for v != n the real lobe leans from the mirror direction
// towards n, the more so the rougher the surface, and reading it at r
// overweights the horizon. Filament's fit of the lobe's dominant direction
// (Lagarde & de Rousiers 2014): r bent towards n by alpha.
FACET_FN vec3 split_sum_direction(vec3 n, vec3 v, real alpha) {
  vec3 r = reflect(-v, n);
  real a = clamp(alpha, real(0), real(1));
  return normalize(r * (real(1) - a) + n * a);
}

// The split sum put together (Karis 2013), for a surface seen from n.v:
// specular = prefiltered radiance x (F0 scale + F90 bias), diffuse = c_diff x
// irradiance / pi. The table integrates Schlick's form F0 + (F90 - F0)(1 -
// v.h)^5: exact for F_SCHLICK and F_NONE, a fit for the exact dielectric and
// conductor by their reflectance at normal incidence and at grazing, where
// every interface reflects everything except a dielectric of index 1 (no
// interface at all: F = 0 everywhere). F90 is that limit, not F evaluated
// near the horizon: lavapipe reassociates 1 - 1 + cos^2 into 0 there. Under
// the horizon policy of the BRDF (n.v <= COS_EPSILON) the surface reflects
// nothing, as with the sampled method.
FACET_FN vec3 split_sum(BrdfParams p, real nv, vec3 prefiltered, vec2 dfg, vec3 irradiance_over_pi) {
  if (nv <= COS_EPSILON) return vec3(real(0));
  bool dielectric = p.f_model == F_DIELECTRIC;
  vec3 f90 =
      vec3(dielectric && p.eta.x == real(1) ? real(0) : real(1), dielectric && p.eta.y == real(1) ? real(0) : real(1),
           dielectric && p.eta.z == real(1) ? real(0) : real(1));
  return prefiltered * (fresnel_F(p, real(1)) * dfg.x + f90 * dfg.y) + p.diffuse * irradiance_over_pi;
}

// Random dimensions one environment/BRDF pair of the sampled method uses:
// 4 for the environment sample (texel as 32 bits, alias, position in the
// texel), 3 for the BRDF sample (lobe, direction). Pair k of seed s uses
// IBL_DIMENSIONS (s IBL_MAX_SAMPLES + k) + 0...6: a different seed draws
// numbers independent of seed 0's (a reference that shares its numbers
// with the estimate it judges would under-report the estimate's error).
const uint IBL_DIMENSIONS = 7u;
const uint IBL_MAX_SAMPLES = 16384u;

FACET_FN uint ibl_dimension(uint seed, uint pair, uint d) {
  return IBL_DIMENSIONS * (seed * IBL_MAX_SAMPLES + pair) + d;
}

// Base-2 radical inverse of i >= 0 (van der Corput): its bits mirrored
// about the binary point, by swapping halves, bytes, nibbles, pairs and
// bits — no loop, so a kernel's sample loop stays far from lavapipe's limit
// of 65535 iterations per invocation. Paired with (i + 1/2) / n it makes
// Hammersley's points: for n = 2^m a (0, m, 2)-net, every elementary box of
// area 1/n holds exactly one point, so the samples are stratified and the
// same on every run and both backends. Both coordinates sit at the middle of
// their 1/n cells: the radical inverse alone starts at 0 and would bias
// every integral by half a cell (5e-4 in DFG at n = 1024).
FACET_FN real radical_inverse_base2(int i) {
  uint bits = uint(i);
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  return real(bits) * real(2.3283064365386963e-10);
}

FACET_FN vec2 hammersley_point(int i, int n) {
  real half_cell = real(0.5) / real(n);
  return vec2(real(i) / real(n) + half_cell, radical_inverse_base2(i) + half_cell);
}

// The weight of prefilter sample m (n = v = r, n.l = 2 (n.m)^2 - 1): with
// half vectors drawn from D(m)(n.m), f (n.l) / pdf(l) for the specular lobe
// is G(l, v) / (n.v) = G(l, n), so weighing by GGX's height-correlated G
// makes the first factor of the split sum the lobe's own average of
// radiance, and the split sum exact wherever v = n. (Karis 2013 weighs by
// n.l instead, which also darkens the lobe's rim but does not match it.)
FACET_FN real prefilter_sample_weight(real alpha, vec3 m) {
  real nl = real(2) * m.z * m.z - real(1);
  if (nl <= real(0)) return real(0);
  return microfacet_G(G_SMITH_GGX_CORRELATED, effective_alpha(alpha), nl, real(1), m.z, m.z);
}

// A coarser texel of the source mip chain averages the 2 x 2 finer texels it
// covers weighted by solid angle, so that the chain keeps the map's integral
// over the sphere: the finer row on top (nearer the pole) has this share of
// the pair's solid angle. A plain box would give the small texels near the
// poles the weight of those at the equator.
FACET_FN real environment_upper_row_share(int coarser_row, int finer_height) {
  real top = environment_row_cos(2 * coarser_row, finer_height);
  real middle = environment_row_cos(2 * coarser_row + 1, finer_height);
  real bottom = environment_row_cos(2 * coarser_row + 2, finer_height);
  return (top - middle) / (top - bottom);
}

// Prefiltered levels by filtered importance sampling (Krivanek & Colbert
// 2008) with n = v = r: sample i of n is a GGX half vector in r's local
// frame; l = reflect(-r, m) has n.l = 2 (n.m)^2 - 1.
FACET_FN vec3 prefilter_sample_normal(int i, int n, real alpha) {
  return sample_microfacet_normal(D_GGX, effective_alpha(alpha), hammersley_point(i, n));
}

// Level of the source's mip chain a sample reads: where a texel is
// as large as the solid angle the sample stands for, Omega_s = 1 / (n pdf)
// with pdf = D(m) / 4 (reflection's Jacobian at v.m = n.m), one level
// coarser (+1) because a box is narrower than the lobe it stands in for.
// Equirectangular texels shrink only in azimuth towards the poles while
// their polar extent, which the chain blurs, stays put: Omega_p is the mean
// texel solid angle, not the row's.
FACET_FN real prefilter_source_lod(real alpha, vec3 m, int samples, int width, int height, int chain_levels) {
  real pdf = real(0.25) * microfacet_D(D_GGX, effective_alpha(alpha), m.z, m.x * m.x + m.y * m.y);
  real omega_s = real(1) / (real(samples) * pdf);
  real omega_p = real(4) * PI / (real(width) * real(height));
  // 0.5 log2(x) as log(x) / (2 ln 2): C++ and GLSL share log, not log2.
  real lod = real(0.72134752044448170368) * log(omega_s / omega_p) + real(1);
  return clamp(lod, real(0), real(chain_levels - 1));
}

// The DFG tables' grid: entry (i, j) of a size x size table sits at
// n.v = (i + 1) / size and sqrt(alpha) = j / (size - 1), so that n.v = 1 (a
// surface seen head-on) and alpha = 1 are entries, not extrapolations, and
// the first column stays clear of n.v = 0, where E(n.v) drops to 0 faster
// than any column spacing follows. Lookups are bilinear at the fractional
// position below, clamped to the table.
FACET_FN real dfg_grid_nv(int i, int size) { return real(i + 1) / real(size); }

FACET_FN real dfg_grid_alpha(int j, int size) { return size > 1 ? sqr(real(j) / real(size - 1)) : real(0); }

FACET_FN vec2 dfg_grid_position(real nv, real alpha, int size) {
  real last = real(size - 1);
  return vec2(clamp(nv * real(size) - real(1), real(0), last), sqrt(clamp(alpha, real(0), real(1))) * last);
}

// One entry of a DFG table: (scale, bias) at n.v = nv and roughness alpha
// for the (d_model, g_model) pair with F = 1 (Schlick's with f0 = 1), over
// `samples` Hammersley points of the lobe's own technique.
FACET_FN vec2 dfg_integrals(int d_model, int g_model, real nv, real alpha, int samples) {
  BrdfParams p;
  p.d_model = d_model;
  p.g_model = g_model;
  p.f_model = F_SCHLICK;
  p.alpha = alpha;
  p.f0 = vec3(real(1));
  p.eta = vec3(real(1));
  p.k = vec3(real(0));
  p.diffuse = vec3(real(0));
  vec3 n = vec3(real(0), real(0), real(1));
  vec3 v = vec3(sqrt(max(real(1) - nv * nv, real(0))), real(0), nv);
  int technique = specular_technique(p);
  vec2 sum = vec2(real(0));
  for (int k = 0; k < samples; ++k) {
    vec3 l = sample_direction(technique, p, n, v, hammersley_point(k, samples));
    real pdf = direction_pdf(technique, p, n, l, v);
    sum += dfg_sample_weight(brdf_terms(p, n, l, v).specular.x, l.z, pdf, real(0.5) * length(l + v));
  }
  return sum / real(samples);
}

// Azimuthal integrals over texel column x of a width-wide map of 1, sin phi,
// cos phi, cos^2 phi and sin phi cos phi (phi = 2 pi (u - 1/2)). With
// y = cos theta, x = sin theta sin phi, z = -sin theta cos phi every SH basis
// function of bands 0-2 is one of these times a polynomial in cos theta and
// sin theta, so a texel's exact SH integral is a product of a column and a
// row integral. Written from the column's centre and half width so that no
// two nearby sines are subtracted.
struct ShColumnIntegrals {
  real one;
  real sin_phi;
  real cos_phi;
  real cos2_phi;
  real sin_cos_phi;
};

FACET_FN ShColumnIntegrals sh_column_integrals(int x, int width) {
  real width_phi = real(2) * PI / real(width);
  real centre = width_phi * (real(x) + real(0.5)) - PI;
  real half_chord = real(2) * sin(real(0.5) * width_phi);
  real chord = sin(width_phi);
  ShColumnIntegrals c;
  c.one = width_phi;
  c.sin_phi = half_chord * sin(centre);
  c.cos_phi = half_chord * cos(centre);
  c.cos2_phi = real(0.5) * (width_phi + chord * cos(real(2) * centre));
  c.sin_cos_phi = real(0.5) * chord * sin(real(2) * centre);
  return c;
}
