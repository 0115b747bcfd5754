// Importance sampling of the BRDF and the matching densities.
//
// A technique maps u in [0,1)^2 to a direction l for a given v. The pdf is
// the density of l over the whole sphere of directions (solid angle), so it
// integrates to 1 there; a sampled l under the horizon is a valid sample on
// which the BRDF is 0.

const int SAMPLE_COSINE = 0;       // cosine-weighted hemisphere (Lambert)
const int SAMPLE_D = 1;            // half vector with density D(m)(n.m), for d_model
const int SAMPLE_GGX_VISIBLE = 2;  // half vector from GGX's visible normals as seen from v

// Orthonormal frame with n as z axis (Duff et al. 2017, branch-free apart
// from the hemisphere sign).
struct Frame {
  vec3 t;
  vec3 b;
  vec3 n;
};

FACET_FN Frame frame_from_normal(vec3 n) {
  real s = n.z >= real(0) ? real(1) : real(-1);
  real a = real(-1) / (s + n.z);
  real b = n.x * n.y * a;
  Frame f;
  f.t = vec3(real(1) + s * sqr(n.x) * a, s * b, -s * n.x);
  f.b = vec3(b, s + sqr(n.y) * a, -n.y);
  f.n = n;
  return f;
}

FACET_FN vec3 to_local(Frame f, vec3 w) { return vec3(dot(w, f.t), dot(w, f.b), dot(w, f.n)); }
FACET_FN vec3 from_local(Frame f, vec3 w) { return w.x * f.t + w.y * f.b + w.z * f.n; }

FACET_FN vec3 spherical_direction(real sin2_theta, real cos_theta, real phi) {
  real sin_theta = sqrt(max(sin2_theta, real(0)));
  return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
}

FACET_FN vec3 sample_cosine_hemisphere(vec2 u) {
  return spherical_direction(u.x, sqrt(real(1) - u.x), real(2) * PI * u.y);
}

// Local frame (n = z): m with density D(m)(n.m), by inverting the CDF of
// the polar angle. sin^2 is formed without 1 - cos^2 where the CDF allows.
FACET_FN vec3 sample_microfacet_normal(int model, real alpha, vec2 u) {
  real a2 = sqr(alpha);
  real cos2 = real(1);
  real sin2 = real(0);
  switch (model) {
    case D_GGX: {
      // tan^2 = alpha^2 u / (1 - u), multiplied through by cos^2.
      real denom = real(1) + (a2 - real(1)) * u.x;
      cos2 = (real(1) - u.x) / denom;
      sin2 = a2 * u.x / denom;
      break;
    }
    case D_BECKMANN: {
      // tan^2 = -alpha^2 ln(1 - u); u = 1 would be the horizon itself.
      real tan2 = -a2 * log(max(real(1) - u.x, real(1.0e-30)));
      cos2 = real(1) / (real(1) + tan2);
      sin2 = tan2 * cos2;
      break;
    }
    case D_BLINN_PHONG:
      // cos = u^(1 / (exponent + 2)).
      cos2 = pow(u.x, real(2) / (blinn_phong_exponent(alpha) + real(2)));
      sin2 = real(1) - cos2;
      break;
  }
  return spherical_direction(sin2, sqrt(cos2), real(2) * PI * u.y);
}

// Local frame: m from GGX's distribution of visible normals for v (v.z > 0),
// D_v(m) = G1(v) max(0, v.m) D(m) / (n.v). Dupuy & Benyoub 2023: in the
// configuration stretched to alpha = 1 the visible normals are a uniform
// spherical cap shifted by v.
FACET_FN vec3 sample_ggx_visible_normal(vec3 v, real alpha, vec2 u) {
  vec3 v_std = normalize(vec3(alpha * v.x, alpha * v.y, v.z));
  real phi = real(2) * PI * u.x;
  real z = (real(1) - u.y) * (real(1) + v_std.z) - v_std.z;
  vec3 m_std = spherical_direction(real(1) - sqr(z), z, phi) + v_std;
  // m_std.z >= 0 by construction; at u.y = 1 the cap point can be -v_std
  // itself and m_std vanish. A floor on z turns that single point into n
  // (a change of measure 0, below D's own resolution elsewhere).
  return normalize(vec3(alpha * m_std.x, alpha * m_std.y, max(m_std.z, real(1.0e-10))));
}

FACET_FN real ggx_visible_normal_pdf(real alpha, real nv, real vm, real nm, real sin2_m) {
  if (nv <= COS_EPSILON) return real(0);
  return smith_G1(D_GGX, alpha, nv) * max(vm, real(0)) * microfacet_D(D_GGX, alpha, nm, sin2_m) / nv;
}

// World space: l for the given technique (l may fall under the horizon).
FACET_FN vec3 sample_direction(int technique, BrdfParams p, vec3 n, vec3 v, vec2 u) {
  Frame f = frame_from_normal(n);
  if (technique == SAMPLE_COSINE) return from_local(f, sample_cosine_hemisphere(u));
  real alpha = effective_alpha(p.alpha);
  vec3 m = technique == SAMPLE_GGX_VISIBLE ? sample_ggx_visible_normal(to_local(f, v), alpha, u)
                                           : sample_microfacet_normal(p.d_model, alpha, u);
  return reflect(-v, from_local(f, m));
}

// Density of l under sample_direction, per unit solid angle.
FACET_FN real direction_pdf(int technique, BrdfParams p, vec3 n, vec3 l, vec3 v) {
  if (technique == SAMPLE_COSINE) return max(dot(n, l), real(0)) * INV_PI;
  // The sampled normal m is the upper-hemisphere one of +-(l + v); the
  // Jacobian of reflection is dw_m / dw_l = 1 / (4 |v.m|). |l + v| at or
  // below COS_EPSILON counts as l = -v, reachable by no microfacet.
  vec3 l_plus_v = l + v;
  real len2 = dot(l_plus_v, l_plus_v);
  if (len2 <= sqr(COS_EPSILON)) return real(0);
  vec3 m = l_plus_v * inversesqrt(len2);
  if (dot(n, m) < real(0)) m = -m;
  real nm = dot(n, m);
  real vm = dot(v, m);
  real sin2_m = sin2_between(n, m);
  real alpha = effective_alpha(p.alpha);
  real pdf_m = technique == SAMPLE_GGX_VISIBLE ? ggx_visible_normal_pdf(alpha, dot(n, v), vm, nm, sin2_m)
                                               : microfacet_D(p.d_model, alpha, nm, sin2_m) * nm;
  return pdf_m / (real(4) * abs(vm));
}
