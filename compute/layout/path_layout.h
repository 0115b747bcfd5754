// The GPU path tracer's records (docs/rendering.md, "Paths"), laid out as
// compute/layout/raycast_layout.h says (valid GLSL and valid C++, 32-bit
// scalars only, no #include); included after it, whose RayRecord a
// continuation ray holds.
#ifndef FACET_LAYOUT_PATH_LAYOUT_H
#define FACET_LAYOUT_PATH_LAYOUT_H

// A continuation ray of the compacted list (paths, docs/rendering.md
// "Paths"), with the camera ray whose path it continues; one that leaves a
// transmissive surface of object `crossedObject` passes over what its
// crossing says (rules/surface/crossing.h: back 0 for none, inside 0 or 1).
struct PathRayRecord {
  RayRecord ray;
  uint path;
  uint crossedObject;
  float crossingBack;
  uint crossingInside;
};

// A path's state, one per camera ray: its throughput T1 ... Tk, and the
// vertex it continues from (eye-relative position, shading and geometric
// normals facing v, the BRDF after textures, energy compensation's specular
// scale). Which paths are still going is the counters' live list.
struct PathState {
  float throughputR;
  float throughputG;
  float throughputB;
  float positionX;
  float positionY;
  float positionZ;
  float nX;
  float nY;
  float nZ;
  float ngX;
  float ngY;
  float ngZ;
  float vX;
  float vY;
  float vZ;
  int dModel;
  int gModel;
  int fModel;
  float alpha;
  float f0R;
  float f0G;
  float f0B;
  float etaR;
  float etaG;
  float etaB;
  float kR;
  float kG;
  float kB;
  float metallic;
  float diffuseR;
  float diffuseG;
  float diffuseB;
  float specularR;
  float specularG;
  float specularB;
  // Transmission (docs/rendering.md, "Transmission and absorption"): the
  // vertex's material, FACET_PATH_* flags and transmission after its
  // texture, and the absorption coefficient of the medium the path is in
  // (0 in air); the object the vertex lies on, whose surface a ray leaving it crosses.
  uint object;
  uint material;
  uint flags;
  float transmission;
  float sigmaR;
  float sigmaG;
  float sigmaB;
  // Limits per lobe kind (docs/rendering.md, "Limits per lobe kind"): the
  // continuations of each kind (PATH_LOBE_*) the path has taken, counted
  // only where the scene sets a limit (LOBE_LIMITS).
  uint diffuseTaken;
  uint glossyTaken;
  uint transmissionTaken;
  // Anisotropy (docs/shading.md, "Anisotropy"): BrdfParams' strength and
  // tangent at the vertex.
  float anisotropy;
  float tangentX;
  float tangentY;
  float tangentZ;
  // Clear coat (docs/shading.md, "Clear coat"): BrdfParams' strength, alpha
  // and coat normal at the vertex.
  float clearcoat;
  float clearcoatAlpha;
  float clearcoatNormalX;
  float clearcoatNormalY;
  float clearcoatNormalZ;
  // Sheen (docs/shading.md, "Sheen"): BrdfParams' color, alpha and the 8
  // knots of its albedo E(mu).
  float sheenR;
  float sheenG;
  float sheenB;
  float sheenAlpha;
  float sheenAlbedo0;
  float sheenAlbedo1;
  float sheenAlbedo2;
  float sheenAlbedo3;
  float sheenAlbedo4;
  float sheenAlbedo5;
  float sheenAlbedo6;
  float sheenAlbedo7;
  // Iridescence (docs/shading.md, "Iridescence"): BrdfParams' factor, film
  // index and thickness.
  float iridescence;
  float iridescenceIor;
  float iridescenceThickness;
};

// PathState.flags: the vertex continues by continue_path_transmissive; v lies
// on the side its outward geometric normal points to; the continuation that
// left the previous vertex went through its surface (a miss then sees the
// environment, which D at that vertex did not count).
const uint FACET_PATH_TRANSMISSIVE = 1u;
const uint FACET_PATH_OUTSIDE = 2u;
const uint FACET_PATH_TRANSMITTED = 4u;

#endif
