#pragma once
// A control cage refined by OpenSubdiv Far into patches, under one of two
// schemes (Subdivision).
//
// Catmull-Clark, feature-adaptive: extraordinary vertices and semi-sharp
// features are isolated to `isolationLevel`, the regular parts become bicubic
// B-spline patches (infinitely sharp creases and boundaries included), and the
// irregular patches left around extraordinary vertices become end caps:
//
//   Gregory  (default) 20-point Gregory-basis patches. They interpolate the
//            exact limit position and tangent plane at every patch corner; the
//            remaining deviation from the true limit shrinks with each
//            isolation level.
//   BSpline  16-point B-spline approximations: cheaper (all patches are
//            polynomial) but only G0-accurate at the extraordinary vertex;
//            offered for speed-against-accuracy charts.
//
// None, the polygons as authored: OpenSubdiv's bilinear scheme, one bilinear
// patch per quad or per corner of any other face (docs/scene-format.md,
// "Subdivision"). Each is degree-elevated to the bicubic Bézier patch it
// equals, so the rest of the pipeline sees the same form as for Catmull-Clark.
//
// Points are computed in double precision (refined vertices through
// PrimvarRefinerReal<double>, end-cap points through the double stencil
// table) and evaluated with OpenSubdiv's own PatchTable::EvaluateBasis.
// One exception, for derivatives of Gregory patches only: OpenSubdiv (unless
// built with OPENSUBDIV_GREGORY_EVAL_TRUE_DERIVATIVES, which Debian's is not)
// differentiates the Bézier patch with its rational interior frozen at
// (u, v), which tilts the normal. We return the true derivatives of the same
// patch (its position is still OpenSubdiv's; the tests hold the two forms
// equal to 1e-12).
//
// Texture coordinates (two sets) and vertex colours, each when the cage has
// them, are OpenSubdiv face-varying channels: patches for the same patches
// (the refinement isolates face-varying features too), of the same kinds
// and evaluated the same way (EvaluateBasisFaceVarying; Gregory derivatives
// exact). A colour thus subdivides as texture coordinates do, each of R, G
// and B as one coordinate of a point.
//
// Parameters: every patch belongs to a ptex face (a quad of the cage, or one
// of the n quads a non-quad face is split into) and covers the square
// domain().u0 + [0, size] x domain().v0 + [0, size] of that face's (u, v).
// Evaluation takes face (u, v) and returns derivatives with respect to it,
// also on the quads of a non-quad face, where OpenSubdiv's are twice that
// (evaluatePatch() rescales them).

#include "scenes/bezier_patch.h"
#include "scenes/control_cage.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace facet::scene {

enum class EndCapBasis { Gregory, BSpline };

// The face-varying channels of a cage (ControlCage): glTF's TEXCOORD_0,
// TEXCOORD_1 and COLOR_0 (RGB).
enum class Channel { Texcoord0, Texcoord1, Color };
constexpr int kChannelCount = 3;

// How a cage becomes a surface: Catmull-Clark's limit surface, or none, the
// polygons as authored.
enum class Subdivision { CatmullClark, None };

struct RefinementSettings {
  // Catmull-Clark only.
  int isolationLevel = 3;  // 1..10; raised to cover every semi-sharp crease (see create())
  EndCapBasis endCaps = EndCapBasis::Gregory;
  Subdivision subdivision = Subdivision::CatmullClark;
};

struct LimitPoint {
  glm::dvec3 position{0.0};
  glm::dvec3 du{0.0};  // dP/du in face parameters
  glm::dvec3 dv{0.0};
};

// Texture coordinates and their derivatives in face parameters.
struct LimitTexcoord {
  glm::dvec2 uv{0.0};
  glm::dvec2 du{0.0};  // d(uv)/du
  glm::dvec2 dv{0.0};
};

struct PatchDomain {
  double u0 = 0.0;
  double v0 = 0.0;
  double size = 1.0;
};

struct PatchInfo {
  int ptexFace = 0;
  int coarseFace = 0;  // the cage face the ptex face came from
  PatchDomain domain;
  int depth = 0;                // refinement level the patch was built at
  unsigned boundaryMask = 0;    // OpenSubdiv edge bits: 1 v=0, 2 u=1, 4 v=1, 8 u=0; 0 when bilinear
  unsigned transitionMask = 0;  // same bits: the neighbour across is one level deeper
  bool gregory = false;
};

struct SurfaceStatistics {
  Subdivision subdivision = Subdivision::CatmullClark;
  int isolationLevel = 0;  // 0 under Subdivision::None
  int cageFaces = 0;
  int ptexFaces = 0;
  int regularPatches = 0;  // the bilinear ones under Subdivision::None
  int endCapPatches = 0;
  int refinedVertices = 0;          // all levels
  int localPoints = 0;              // end-cap points
  std::size_t openSubdivBytes = 0;  // patch table + point buffer + local-point stencils
};

std::string describe(const SurfaceStatistics& stats);

class SubdivisionSurface {
 public:
  // Throws InputError when the cage breaks a rule OpenSubdiv relies on
  // without checking (an index out of range, a face of fewer than 3
  // vertices, a non-finite position) or when OpenSubdiv rejects the
  // topology; non-manifold edges and vertices, a vertex repeated within a
  // face and vertices no face uses are accepted, as OpenSubdiv accepts them.
  // Catmull-Clark's isolation level is max(settings.isolationLevel,
  // ceil(sharpest semi-sharp crease or corner)), capped at 10, so semi-sharp
  // features decay completely before patches are built (they are then exact,
  // not end caps).
  static SubdivisionSurface create(const ControlCage& cage, const RefinementSettings& settings = {});

  SubdivisionSurface(SubdivisionSurface&&) noexcept;
  SubdivisionSurface& operator=(SubdivisionSurface&&) noexcept;
  ~SubdivisionSurface();

  int patchCount() const;
  const PatchInfo& patch(int index) const;
  const BezierPatch& bezierPatch(int index) const;
  // A mesh as authored with normals: the shading normals at the patch's four
  // corners (counter-clockwise from (0, 0), as its points), which shading
  // interpolates bilinearly; nullptr otherwise.
  const std::array<glm::dvec3, 4>* authoredNormals(int index) const;
  // Where such a mesh also has tangents (ControlCage::faceVertexTangents),
  // likewise at the four corners; nullptr otherwise.
  const std::array<glm::dvec4, 4>* authoredTangents(int index) const;
  bool hasAuthoredTangents() const;

  // The limit surface on patch `index` at face parameters (u, v).
  LimitPoint evaluatePatch(int index, double u, double v) const;

  // Whether the cage carried a channel (TEXCOORD_0 for hasTexcoords()).
  bool hasChannel(Channel channel) const;
  bool hasTexcoords() const { return hasChannel(Channel::Texcoord0); }
  // A channel over patch `index` as a Bézier patch in the patch's (s, t),
  // points (u, v, 0) or (r, g, b) laid out as bezierPatch()'s; nullptr
  // without the channel.
  const BezierPatch* channelPatch(Channel channel, int index) const;
  const BezierPatch* texcoordPatch(int index) const { return channelPatch(Channel::Texcoord0, index); }
  // A channel on patch `index` at face parameters (u, v), from OpenSubdiv's
  // face-varying patch (EvaluateBasisFaceVarying; Gregory derivatives exact,
  // as for positions); zero without the channel.
  LimitPoint evaluateChannel(Channel channel, int index, double u, double v) const;
  // Texture coordinate set `set` (0 or 1); zero without it.
  LimitTexcoord evaluateTexcoord(int index, double u, double v, int set = 0) const;
  // The vertex colour, white (1, 1, 1) without one.
  glm::dvec3 evaluateColor(int index, double u, double v) const;
  // The patch containing face point (u, v), found by Far::PatchMap; empty
  // over holes.
  std::optional<int> findPatch(int ptexFace, double u, double v) const;
  std::optional<LimitPoint> evaluateFace(int ptexFace, double u, double v) const;

  // Box of all patch control hulls: it encloses the limit surface.
  const Aabb& bounds() const;
  const SurfaceStatistics& statistics() const;

 private:
  struct Impl;
  explicit SubdivisionSurface(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet::scene
