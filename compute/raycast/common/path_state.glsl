// Paths (docs/rendering.md, "Paths"): a camera ray's path state as the
// kernels pack and unpack it (compute/layout/path_layout.h's PathState).
#ifndef FACET_RAYCAST_PATH_STATE_GLSL
#define FACET_RAYCAST_PATH_STATE_GLSL

#include "rules/language.glsl"
#include "rules/shading/path_step.h"
#include "rules/shading/transmissive_continuation.h"

// What a path carries for transmission (PathState's last members).
struct PathMedium {
  uint object;  // the vertex's
  uint material;
  uint flags;          // FACET_PATH_*
  float transmission;  // the vertex's, after any texture (TransmissionParams.transmission)
  vec3 sigma;          // of the medium the path travels in
};

// The continuations of each lobe kind a path has taken, indexed by PATH_LOBE_*.
uvec3 path_lobes_taken(PathState s) { return uvec3(s.diffuseTaken, s.glossyTaken, s.transmissionTaken); }

PathState pack_path_state(vec3 throughput, PathVertex x, PathMedium medium, uvec3 taken) {
  BrdfParams p = x.params;
  return PathState(throughput.x, throughput.y, throughput.z, x.position.x, x.position.y,
                   x.position.z, x.n.x, x.n.y, x.n.z, x.ng.x, x.ng.y, x.ng.z, x.v.x, x.v.y, x.v.z, p.d_model,
                   p.g_model, p.f_model, p.alpha, p.f0.x, p.f0.y, p.f0.z, p.eta.x, p.eta.y, p.eta.z, p.k.x, p.k.y,
                   p.k.z, p.metallic, p.diffuse.x, p.diffuse.y, p.diffuse.z, x.specular_scale.x, x.specular_scale.y,
                   x.specular_scale.z, medium.object, medium.material, medium.flags, medium.transmission, medium.sigma.x, medium.sigma.y,
                   medium.sigma.z, taken.x, taken.y, taken.z, p.anisotropy, p.tangent.x, p.tangent.y,
                   p.tangent.z, p.clearcoat, p.clearcoat_alpha, p.clearcoat_normal.x, p.clearcoat_normal.y,
                   p.clearcoat_normal.z, p.sheen_color.x, p.sheen_color.y, p.sheen_color.z, p.sheen_alpha,
                   p.sheen_albedo_near.x, p.sheen_albedo_near.y, p.sheen_albedo_near.z, p.sheen_albedo_near.w,
                   p.sheen_albedo_far.x, p.sheen_albedo_far.y, p.sheen_albedo_far.z, p.sheen_albedo_far.w,
                   p.iridescence, p.iridescence_ior, p.iridescence_thickness);
}

vec3 path_throughput(PathState s) { return vec3(s.throughputR, s.throughputG, s.throughputB); }

PathMedium path_medium(PathState s) {
  return PathMedium(s.object, s.material, s.flags, s.transmission, vec3(s.sigmaR, s.sigmaG, s.sigmaB));
}

// A material record's transmission as the shared rules take it.
TransmissionParams transmission_params(MaterialRecord m) {
  TransmissionParams t;
  t.transmission = m.transmission;
  t.ior = m.ior;
  t.thin_walled = m.thinWalled != 0u;
  t.sigma = vec3(m.sigmaR, m.sigmaG, m.sigmaB);
  t.thickness = m.thickness;
  return t;
}

// The vertex a path continues from, as its state holds it: where it is
// transmissive, with the transmission of the material its medium names.
PathVertex path_vertex(PathState s, bool transmissive, TransmissionParams transmission) {
  BrdfParams p;
  p.d_model = s.dModel;
  p.g_model = s.gModel;
  p.f_model = s.fModel;
  p.alpha = s.alpha;
  p.f0 = vec3(s.f0R, s.f0G, s.f0B);
  p.eta = vec3(s.etaR, s.etaG, s.etaB);
  p.k = vec3(s.kR, s.kG, s.kB);
  p.metallic = s.metallic;
  p.diffuse = vec3(s.diffuseR, s.diffuseG, s.diffuseB);
  p.anisotropy = s.anisotropy;
  p.tangent = vec3(s.tangentX, s.tangentY, s.tangentZ);
  p.clearcoat = s.clearcoat;
  p.clearcoat_alpha = s.clearcoatAlpha;
  p.clearcoat_normal = vec3(s.clearcoatNormalX, s.clearcoatNormalY, s.clearcoatNormalZ);
  p.sheen_color = vec3(s.sheenR, s.sheenG, s.sheenB);
  p.sheen_alpha = s.sheenAlpha;
  p.sheen_albedo_near = vec4(s.sheenAlbedo0, s.sheenAlbedo1, s.sheenAlbedo2, s.sheenAlbedo3);
  p.sheen_albedo_far = vec4(s.sheenAlbedo4, s.sheenAlbedo5, s.sheenAlbedo6, s.sheenAlbedo7);
  p.iridescence = s.iridescence;
  p.iridescence_ior = s.iridescenceIor;
  p.iridescence_thickness = s.iridescenceThickness;
  return PathVertex(vec3(s.positionX, s.positionY, s.positionZ), vec3(s.nX, s.nY, s.nZ), vec3(s.ngX, s.ngY, s.ngZ),
                    vec3(s.vX, s.vY, s.vZ), p, vec3(s.specularR, s.specularG, s.specularB), transmissive,
                    transmission, (s.flags & FACET_PATH_OUTSIDE) != 0u);
}

#endif
