// The GPU ray caster's buffers as both languages see them. The layouts of
// compute/layout/ are valid GLSL and valid C++:
//   - members are 32-bit scalars (float, uint, int) or structs of them, no
//     vectors and no arrays, so std430, std140 and C++ agree without padding;
//   - constants are `const uint` at file scope;
//   - no #include, no C++-only syntax.
// C++ includes them through engine/gpu_backend/raycast_layout.h, which
// static_asserts the sizes; tests/engine/gpu_backend/gpu_scene_test.cpp checks the
// offsets glslang chose.
#ifndef FACET_LAYOUT_RAYCAST_LAYOUT_H
#define FACET_LAYOUT_RAYCAST_LAYOUT_H

// Where one object's data starts in the concatenated scene arrays; every
// index is absolute. Its micro-grid has k x k cells per patch; each patch's
// quadtree (compute/layout/wide_bvh.h) has `quadtreeLevels` levels of nodes
// over a side^2 grid, side = 2^quadtreeLevels >= k, whose last level holds
// 2 x 2 cells a node.
struct ObjectRange {
  uint firstPatch;  // PatchRecord and patch header index
  uint patchCount;
  uint patchIdOffset;  // patch and cage-face ids count on across objects
  uint faceIdOffset;
  uint material;
  uint rate;  // k
  uint quadtreeLevels;
  uint firstQuadtreeNode;  // patch p's quadtree starts at firstQuadtreeNode + p * quadtreeNodes
  uint quadtreeNodes;
  uint firstBlock;         // dicing: the object's first 2 x 2 block of cells
  uint firstCell;          // exact: FACET_CELL_TEXELS of bounds per cell
  uint firstGridVertex;    // tessellated: (k + 1)^2 limit points per patch
  uint firstEdgeMidpoint;  // tessellated: 4 k per patch (those of unsplit edges unused)
  uint channels;           // its face-varying channels, FACET_CHANNEL_* bits (patch_records.h)
  uint flags;              // FACET_OBJECT_* bits
  // FACET_OBJECT_CUTOUT (rules/surface/cutout.h): MASK's cutoff, the alpha
  // factor and the texture slot (a TextureSlotRecord's fields) of its alpha.
  float alphaCutoff;
  float alphaFactor;
  uint alphaTexture;
  float alphaOffsetX;
  float alphaOffsetY;
  float alphaCosRotation;
  float alphaSinRotation;
  float alphaScaleX;
  float alphaScaleY;
  uint alphaTexCoord;
};

// The object passes over its back faces (rules/surface/back_face.h).
const uint FACET_OBJECT_CULL_BACK_FACES = 1u;
// The object passes over where its alpha is below its cutoff; with FACET_OBJECT_BLEND, with probability 1 - alpha.
const uint FACET_OBJECT_CUTOUT = 2u;
const uint FACET_OBJECT_BLEND = 32u;
// The preview's ground in the paths (rules/shading/shadow_catcher.h): camera rays pass over it,
// continuation rays find the background it catches shadows on.
const uint FACET_OBJECT_SHADOW_CATCHER = 4u;
// Every ray from inside the object crosses its surface (scene::sealsInside): where its material
// is a solid's, the environment cannot reach its inside (environment_sealed_off).
const uint FACET_OBJECT_SEALED = 8u;
// The preview's holdout (scene::Object::holdout): camera rays see black there and end; paths see it as it is.
const uint FACET_OBJECT_HOLDOUT = 16u;
// A mesh as authored with tangents (ControlCage::faceVertexTangents): each
// patch's 4 texels of authored normals are followed by 4 of its corners'
// tangents (xyz, and the bitangent's sign in w).
const uint FACET_OBJECT_TANGENTS = 64u;

// A ray from `origin` along `direction`, over [tMin, tMax).
struct RayRecord {
  float originX;
  float originY;
  float originZ;
  float tMin;
  float directionX;
  float directionY;
  float directionZ;
  float tMax;
};

// A shadow ray of the compacted list, with the light slot it decides.
struct ShadowRayRecord {
  RayRecord ray;
  uint slot;
};

// Counted by the kernels, read back per band. Each list's length comes with
// the workgroup grid of the pass that works it off (indirect dispatch).
struct RenderCounters {
  uint shadowRays;  // appended by the surface kernel
  uint shadowX;
  uint shadowY;
  uint shadowZ;
  uint cameraFallbacks;  // exact cells of camera rays left to subdivision
  uint cameraFallbackX;
  uint cameraFallbackY;
  uint cameraFallbackZ;
  uint shadowFallbacks;  // the same for shadow rays
  uint shadowFallbackX;
  uint shadowFallbackY;
  uint shadowFallbackZ;
  uint pathRays;  // continuation rays, appended by the continuation kernel (paths only)
  uint pathX;
  uint pathY;
  uint pathZ;
  uint pathHits;  // rays of this bounce that hit: camera rays at bounce 0, then continuation rays
  // Paths that go on from this bounce's vertices (their camera rays),
  // appended by the surface kernel: the next bounce continues these alone.
  // Last, so that a bounce can clear the counters before it and keep them.
  uint livePaths;
  uint liveX;
  uint liveY;
  uint liveZ;
};

// An exact cell that Newton did not settle, deferred to the fallback pass (compute/raycast/finish/fallback.comp):
// the ray (camera or shadow ray index) and the cell; for camera rays the fallback adds the closest root it found.
struct FallbackRecord {
  uint ray;
  uint cell;  // its reference (compute/layout/wide_bvh.h)
  uint object;
  float t;
  uint patchIndex;
  float s;
  float tParam;
};

// The closest hit; patchIndex == FACET_NO_HIT on a miss. (s, t) is patch-local.
// The geometric normal is the micro-triangle's (tessellated only; the exact
// method's is the limit normal, found when shading).
struct HitRecord {
  float t;
  uint patchIndex;  // absolute PatchRecord index
  uint object;
  float s;
  float tParam;
  float geometricX;
  float geometricY;
  float geometricZ;
};

const uint FACET_NO_HIT = 0xFFFFFFFFu;

// A punctual light in world space; the spot cones are given as cosines.
const uint FACET_LIGHT_DIRECTIONAL = 0u;
const uint FACET_LIGHT_POINT = 1u;
const uint FACET_LIGHT_SPOT = 2u;
struct LightRecord {
  uint type;
  float colorR;
  float colorG;
  float colorB;
  float positionX;
  float positionY;
  float positionZ;
  float cosOuter;
  float directionX;
  float directionY;
  float directionZ;
  float cosInner;
};

// A texture a material reads (an index into the texture table of
// compute/raycast/common/textures.glsl, FACET_NO_TEXTURE for none) and its
// KHR_texture_transform.
const uint FACET_NO_TEXTURE = 0xFFFFFFFFu;

// A material without energy compensation (MaterialRecord.compensationTable).
const uint FACET_NO_COMPENSATION = 0xFFFFFFFFu;
struct TextureSlotRecord {
  uint texture;
  float offsetX;
  float offsetY;
  float cosRotation;
  float sinRotation;
  float scaleX;
  float scaleY;
  uint texCoord;  // the set of texture coordinates it reads, 0 or 1
};

// A material as BrdfParams wants it (rules/shading/brdf.h), the radiance it emits, and, when
// `textured`, the glTF parameters its textures modulate per hit (rules/shading/textured_material.h).
struct MaterialRecord {
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
  float diffuseR;
  float diffuseG;
  float diffuseB;
  uint dfgTable;  // prefiltered environment: which DFG table (by the material's D and G)
  float emissionR;
  float emissionG;
  float emissionB;
  uint textured;
  float baseR;
  float baseG;
  float baseB;
  float metallic;
  float roughness;
  float normalScale;
  float occlusionStrength;
  float specularR;  // KHR_materials_specular's, where `textured` is 1: F(0) of the index x specularColorFactor
  float specularG;
  float specularB;
  float specular;  // specularFactor
  TextureSlotRecord baseColorTexture;
  TextureSlotRecord metallicRoughnessTexture;
  TextureSlotRecord normalTexture;
  TextureSlotRecord occlusionTexture;
  TextureSlotRecord emissiveTexture;
  uint compensationTable;  // energy compensation's table (by D and G), or FACET_NO_COMPENSATION
  // rules/shading/transmissive_continuation.h's TransmissionParams, used
  // where `transmissive` is 1.
  uint transmissive;
  float transmission;
  float ior;
  uint thinWalled;
  float sigmaR;
  float sigmaG;
  float sigmaB;
  float thickness;
  TextureSlotRecord transmissionTexture;  // R scales `transmission` where `textured`
  // Anisotropy (docs/shading.md, "Anisotropy"): the strength, and the
  // tangent's rotation about the normal as cos and sin.
  float anisotropy;
  float anisotropyCos;
  float anisotropySin;
  // Clear coat (docs/shading.md, "Clear coat"): the strength, the coat's
  // microfacet alpha, and the prefiltered environment's DFG table of its
  // (GGX, height-correlated Smith) lobe.
  float clearcoat;
  float clearcoatAlpha;
  uint coatDfgTable;
  // Sheen (docs/shading.md, "Sheen"): the color, alpha and the 8 knots of
  // the lobe's albedo E(mu), as BrdfParams carries them.
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
  uint unlit;  // KHR_materials_unlit, where `textured` is 1: the base colour is emitted
  // The layers' textures, where `textured` is 1 (materials::MaterialTextures).
  TextureSlotRecord clearcoatTexture;
  TextureSlotRecord clearcoatRoughnessTexture;
  TextureSlotRecord clearcoatNormalTexture;
  float clearcoatNormalScale;
  TextureSlotRecord sheenColorTexture;
  TextureSlotRecord anisotropyTexture;
  TextureSlotRecord specularTexture;       // A scales `specular`
  TextureSlotRecord specularColorTexture;  // RGB (sRGB) scales specularR, G, B
  // Iridescence (docs/shading.md, "Iridescence"): the factor, the film's
  // index and its thickness in nanometres, as BrdfParams carries them.
  float iridescence;
  float iridescenceIor;
  float iridescenceThickness;
  // Its textures, where `textured` is 1: R scales `iridescence`, G places
  // the thickness between the minimum and iridescenceThickness.
  TextureSlotRecord iridescenceTexture;
  TextureSlotRecord iridescenceThicknessTexture;
  float iridescenceThicknessMinimum;
  // The sheen's roughness texture, where `textured` is 1: A scales the
  // factor (sheenRoughnessFactor), its knots read between the sheen's rows.
  TextureSlotRecord sheenRoughnessTexture;
  float sheenRoughnessFactor;
};

// What the camera-side kernels need, one uniform block (std140 agrees: all
// members are scalars, the camera first).
struct FrameParams {
  float eyeX;
  float eyeY;
  float eyeZ;
  float tanHalfFovY;
  float forwardX;
  float forwardY;
  float forwardZ;
  float aspect;
  float rightX;
  float rightY;
  float rightZ;
  float width;
  float upX;
  float upY;
  float upZ;
  float height;
  // The window of the image a render covers (a crop, or the whole image),
  // and the band of its pixels this pass renders, counted along the
  // window's rows (compute/raycast/common/band_pixels.glsl).
  uint windowX;
  uint windowY;
  uint windowWidth;
  uint firstPixel;
  uint pixelCount;
  uint strata;        // samples per pixel = strata^2
  uint raysPerPixel;  // 1 when strata == 1, else the centre ray plus strata^2
  uint objectCount;
  uint rootNode;         // of the scene's BVH
  uint cellBlockCount;   // dicing: 2 x 2 blocks of cells in all
  uint gridVertexCount;  // tessellated dicing: grid vertices, then edge midpoints
  uint edgeMidpointCount;
  uint patchCount;
  float tolerance;        // exact method: largest ray-to-surface distance of a root
  float minimumPiece;     // exact method: pieces are not split below this size
  float shadowOffset;     // shadow_ray_offset (rules/shading/lights.h)
  uint slotsPerRay;       // shadow-ray slots per camera ray: one per light, then the environment's
  uint fallbackCapacity;  // records in each fallback list
  // The environment (compute/raycast/shading/environment.glsl); offsets count
  // texels of the environment tables (the map's texels have their own).
  float environmentIntensity;
  float environmentCosRotation;
  float environmentSinRotation;
  uint environmentSamples;  // sampled: pairs per camera sample
  uint environmentSeed;
  uint environmentWidth;
  uint environmentHeight;
  uint levelCount;  // prefiltered: radiance levels, (first texel, width, height, 0) each
  uint shOffset;    // prefiltered: 9 RGB SH coefficients
  uint dfgOffset;   // prefiltered: the DFG tables, each dfgSize^2 (scale, bias) texels
  uint dfgSize;
  uint compensationSize;  // energy compensation: each of its tables is compensationSize^2 (scale, bias) texels
  // Paths: the vertex the bounce's continuation rays leave (0 for the camera
  // rays' pass), and the scene's environment seed that keys their numbers
  // (environmentSeed is then that of the vertex they hit).
  uint pathVertex;
  uint pathSeed;
  // Limits per lobe kind: the continuations of each kind a path may take
  // (render.diffuse_bounces, glossy_bounces, transmission_bounces); below 0,
  // none. Read only by kernels specialized with LOBE_LIMITS = 1.
  int diffuseBounces;
  int glossyBounces;
  int transmissionBounces;
  // The absorption of the solid around the eye (scene::cameraMedium), 0 in
  // air: camera rays cross it to their first vertex, and paths start in it.
  float eyeSigmaR;
  float eyeSigmaG;
  float eyeSigmaB;
};

// The AOVs of one pixel (beauty is written separately, as a vec4).
struct PixelAovs {
  float depth;
  float positionX;
  float positionY;
  float positionZ;
  float geometricX;
  float geometricY;
  float geometricZ;
  float shadingX;
  float shadingY;
  float shadingZ;
  uint patchId;
  uint faceId;
  float u;
  float v;
  float texcoordS;  // texture coordinates (0 on misses and without them)
  float texcoordT;
};

#endif
