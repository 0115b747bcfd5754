// Internal: what the files of SubdivisionSurface share. Only
// scenes/subdivision_*.cpp include this file.
#pragma once

#include "scenes/subdivision_surface.h"

#include <glm/vec3.hpp>

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <array>
#include <memory>
#include <vector>

namespace facet::scene {

namespace Far = OpenSubdiv::Far;

namespace detail {

// The point type OpenSubdiv's refiner and stencil tables interpolate.
struct OsdPoint {
  glm::dvec3 p{0.0};
  void Clear() { p = glm::dvec3(0.0); }
  void AddWithWeight(const OsdPoint& src, double weight) { p += weight * src.p; }
};

// subdivision_refiner.cpp: the cage checked against the rules OpenSubdiv
// relies on (InputError otherwise) and handed to its refiner.
std::unique_ptr<Far::TopologyRefiner> createRefiner(const ControlCage& cage, Subdivision subdivision);
int isolationLevelFor(const ControlCage& cage, const RefinementSettings& settings);

// A cage's channel as OpenSubdiv takes it: its name in messages, its values
// as points and the value index of every face corner (empty without it).
struct ChannelValues {
  const char* name;
  std::vector<glm::dvec3> values;
  const std::vector<int>& corners;
};
ChannelValues channelValues(const ControlCage& cage, Channel channel);

// subdivision_bezier.cpp: one patch of OpenSubdiv's (vertex or face-varying)
// in Bézier form, its control points `cvs` into `points`.
BezierPatch bezierFromPatch(Far::PatchDescriptor::Type type, Far::ConstIndexArray cvs,
                            const std::vector<OsdPoint>& points, unsigned boundaryMask);

}  // namespace detail

// Everything evaluation needs; the refiner is dropped once the patch table
// and the points exist.
struct SubdivisionSurface::Impl {
  std::unique_ptr<Far::PatchTable> patchTable;
  std::unique_ptr<Far::PatchMap> patchMap;
  std::vector<detail::OsdPoint> points;  // refined levels, then local points
  std::vector<Far::PatchTable::PatchHandle> handles;
  std::vector<PatchInfo> patches;
  std::vector<BezierPatch> bezierPatches;
  std::vector<std::array<glm::dvec3, 4>> authoredNormals;   // per patch, or empty
  std::vector<std::array<glm::dvec4, 4>> authoredTangents;  // per patch, or empty
  // Per channel (Channel's order), the cage has it when `fvar` (its
  // OpenSubdiv channel) is >= 0: its values, refined levels then local
  // points; and per patch the face-varying patch as OpenSubdiv has it and in
  // Bézier form.
  struct FaceVarying {
    int fvar = -1;
    std::vector<detail::OsdPoint> points;
    std::vector<Far::PatchDescriptor::Type> types;
    std::vector<BezierPatch> patches;
  };
  std::array<FaceVarying, kChannelCount> channels;
  Aabb bounds;
  SurfaceStatistics statistics;
};

}  // namespace facet::scene
