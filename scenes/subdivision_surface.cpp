#include "scenes/subdivision_surface.h"

#include "scenes/input_error.h"

#include <glm/geometric.hpp>

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace facet::scene {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

namespace {

// The point type OpenSubdiv's refiner and stencil tables interpolate.
struct OsdPoint {
  glm::dvec3 p{0.0};
  void Clear() { p = glm::dvec3(0.0); }
  void AddWithWeight(const OsdPoint& src, double weight) { p += weight * src.p; }
};

// OpenSubdiv reports topology errors through a process-wide callback; keep
// the last message so it can go into the exception. (Refining two cages on
// two threads at once would mix messages, nothing worse.)
thread_local std::string osdLastError;

struct OsdMessageCapture {
  OsdMessageCapture() {
    osdLastError.clear();
    Far::SetErrorCallback([](Far::ErrorType, const char* message) { osdLastError = message; });
    // Warnings (non-manifold topology OpenSubdiv accepts) are not errors.
    Far::SetWarningCallback([](const char*) {});
  }
  ~OsdMessageCapture() {
    Far::SetErrorCallback(nullptr);
    Far::SetWarningCallback(nullptr);
  }
};

Sdc::Options sdcOptions(const SubdivisionOptions& options) {
  Sdc::Options sdc;
  switch (options.boundary) {
    case BoundaryInterpolation::None:
      sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
      break;
    case BoundaryInterpolation::EdgeOnly:
      sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
      break;
    case BoundaryInterpolation::EdgeAndCorner:
      sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
      break;
  }
  sdc.SetFVarLinearInterpolation(static_cast<Sdc::Options::FVarLinearInterpolation>(options.faceVarying));
  sdc.SetCreasingMethod(options.creasing == CreasingMethod::Chaikin ? Sdc::Options::CREASE_CHAIKIN
                                                                    : Sdc::Options::CREASE_UNIFORM);
  sdc.SetTriangleSubdivision(options.triangles == TriangleSubdivision::Smooth ? Sdc::Options::TRI_SUB_SMOOTH
                                                                              : Sdc::Options::TRI_SUB_CATMARK);
  return sdc;
}

void validateTexcoords(const ControlCage& cage) {
  auto fail = [&cage](const std::string& rule, const std::string& detail) {
    throw InputError(cage.source, 0, rule, detail);
  };
  if (cage.faceVertexTexcoords.empty()) {
    if (!cage.texcoords.empty()) fail("texture coordinates", "values given, but no face corner uses them");
    return;
  }
  if (cage.faceVertexTexcoords.size() != cage.faceVertexIndices.size())
    fail("texture coordinates", std::to_string(cage.faceVertexTexcoords.size()) + " indices for " +
                                    std::to_string(cage.faceVertexIndices.size()) + " face corners");
  for (int index : cage.faceVertexTexcoords)
    if (index < 0 || index >= int(cage.texcoords.size()))
      fail("index out of range", "texture coordinate " + std::to_string(index) + " of " +
                                     std::to_string(cage.texcoords.size()));
  for (const glm::dvec2& t : cage.texcoords)
    if (!std::isfinite(t.x) || !std::isfinite(t.y))
      fail("non-finite value", "a texture coordinate is NaN or infinite");
}

// OpenSubdiv trusts its input (an out-of-range index is undefined
// behaviour, not an error), and cages also come from front-ends other than
// the OBJ reader, which reports the same rules with line numbers.
void validateCage(const ControlCage& cage) {
  auto fail = [&cage](const std::string& rule, const std::string& detail) {
    throw InputError(cage.source, 0, rule, detail);
  };
  if (cage.faceVertexCounts.empty()) fail("empty cage", "no faces");
  for (const glm::dvec3& p : cage.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail("non-finite value", "a vertex position is NaN or infinite");
  size_t offset = 0;
  std::set<std::pair<int, int>> edges;
  for (int face = 0; face < cage.faceCount(); ++face) {
    const int count = cage.faceVertexCounts[face];
    if (count < 3) fail("degenerate face", "face " + std::to_string(face) + " has fewer than 3 vertices");
    if (offset + count > cage.faceVertexIndices.size())
      fail("index out of range", "face vertex counts exceed the index list");
    for (int c = 0; c < count; ++c) {
      const int vertex = cage.faceVertexIndices[offset + c];
      if (vertex < 0 || vertex >= cage.vertexCount())
        fail("index out of range", "face " + std::to_string(face) + " uses vertex " + std::to_string(vertex));
      edges.insert(std::minmax(vertex, cage.faceVertexIndices[offset + (c + 1) % count]));
    }
    offset += count;
  }
  for (const CreaseEdge& crease : cage.creases)
    if (!edges.count(std::minmax(crease.v0, crease.v1)))
      fail("crease on a non-edge", std::to_string(crease.v0) + "-" + std::to_string(crease.v1) + " is not an edge");
  for (const CornerVertex& corner : cage.corners)
    if (corner.vertex < 0 || corner.vertex >= cage.vertexCount())
      fail("index out of range", "corner vertex " + std::to_string(corner.vertex));
  for (int hole : cage.holes)
    if (hole < 0 || hole >= cage.faceCount()) fail("index out of range", "hole face " + std::to_string(hole));
  validateTexcoords(cage);
}

std::unique_ptr<Far::TopologyRefiner> createRefiner(const ControlCage& cage, Subdivision subdivision) {
  validateCage(cage);
  std::vector<Far::Index> creasePairs;
  std::vector<float> creaseWeights;
  for (const CreaseEdge& crease : cage.creases) {
    creasePairs.push_back(crease.v0);
    creasePairs.push_back(crease.v1);
    creaseWeights.push_back(crease.sharpness);
  }
  std::vector<Far::Index> cornerVertices;
  std::vector<float> cornerWeights;
  for (const CornerVertex& corner : cage.corners) {
    cornerVertices.push_back(corner.vertex);
    cornerWeights.push_back(corner.sharpness);
  }

  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = cage.vertexCount();
  descriptor.numFaces = cage.faceCount();
  descriptor.numVertsPerFace = cage.faceVertexCounts.data();
  descriptor.vertIndicesPerFace = cage.faceVertexIndices.data();
  descriptor.numCreases = static_cast<int>(cage.creases.size());
  descriptor.creaseVertexIndexPairs = creasePairs.data();
  descriptor.creaseWeights = creaseWeights.data();
  descriptor.numCorners = static_cast<int>(cage.corners.size());
  descriptor.cornerVertexIndices = cornerVertices.data();
  descriptor.cornerWeights = cornerWeights.data();
  descriptor.numHoles = static_cast<int>(cage.holes.size());
  descriptor.holeIndices = cage.holes.data();
  Far::TopologyDescriptor::FVarChannel texcoords;
  texcoords.numValues = int(cage.texcoords.size());
  texcoords.valueIndices = cage.faceVertexTexcoords.data();
  if (!cage.faceVertexTexcoords.empty()) {
    descriptor.numFVarChannels = 1;
    descriptor.fvarChannels = &texcoords;
  }

  OsdMessageCapture capture;
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      descriptor, Factory::Options(subdivision == Subdivision::None ? Sdc::SCHEME_BILINEAR : Sdc::SCHEME_CATMARK,
                                   sdcOptions(cage.options))));
  if (!refiner)
    throw InputError(cage.source, 0, "topology rejected by OpenSubdiv",
                     osdLastError.empty() ? "no reason given" : osdLastError);
  return refiner;
}

int isolationLevelFor(const ControlCage& cage, const RefinementSettings& settings) {
  float sharpest = 0.0f;
  for (const CreaseEdge& crease : cage.creases)
    if (crease.sharpness < Sdc::Crease::SHARPNESS_INFINITE) sharpest = std::max(sharpest, crease.sharpness);
  for (const CornerVertex& corner : cage.corners)
    if (corner.sharpness < Sdc::Crease::SHARPNESS_INFINITE) sharpest = std::max(sharpest, corner.sharpness);
  int level = std::max(settings.isolationLevel, static_cast<int>(std::ceil(sharpest)));
  return std::clamp(level, 1, 10);
}

// Folds OpenSubdiv's boundary rule into explicit phantom rows and columns
// (the basis adjustment of a boundary patch equals extrapolating the missing
// row as 2*edge - inner), then converts the uniform B-spline to Bézier form.
BezierPatch bezierFromBSpline(const std::array<glm::dvec3, 16>& cvs, unsigned boundaryMask) {
  std::array<glm::dvec3, 16> g = cvs;
  auto at = [&g](int row, int col) -> glm::dvec3& { return g[4 * row + col]; };
  for (int col = 0; col < 4; ++col) {
    if (boundaryMask & 1u) at(0, col) = 2.0 * at(1, col) - at(2, col);
    if (boundaryMask & 4u) at(3, col) = 2.0 * at(2, col) - at(1, col);
  }
  for (int row = 0; row < 4; ++row) {
    if (boundaryMask & 8u) at(row, 0) = 2.0 * at(row, 1) - at(row, 2);
    if (boundaryMask & 2u) at(row, 3) = 2.0 * at(row, 2) - at(row, 1);
  }
  auto toBezier = [](const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3) {
    return std::array<glm::dvec3, 4>{(p0 + 4.0 * p1 + p2) / 6.0, (2.0 * p1 + p2) / 3.0, (p1 + 2.0 * p2) / 3.0,
                                     (p1 + 4.0 * p2 + p3) / 6.0};
  };
  std::array<glm::dvec3, 16> rows{};
  for (int row = 0; row < 4; ++row) {
    auto b = toBezier(at(row, 0), at(row, 1), at(row, 2), at(row, 3));
    for (int col = 0; col < 4; ++col) rows[4 * row + col] = b[col];
  }
  BezierPatch patch;
  for (int col = 0; col < 4; ++col) {
    auto b = toBezier(rows[col], rows[4 + col], rows[8 + col], rows[12 + col]);
    for (int row = 0; row < 4; ++row) patch.points[4 * row + col] = b[row];
  }
  return patch;
}

// The bilinear patch through OpenSubdiv's four QUADS points (counter-clockwise
// from (0, 0)) as the bicubic Bézier patch it equals: P_ij = bilinear(i/3, j/3).
BezierPatch bezierFromBilinear(const std::array<glm::dvec3, 4>& corners) {
  BezierPatch patch;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      patch.points[4 * j + i] = (double((3 - i) * (3 - j)) * corners[0] + double(i * (3 - j)) * corners[1] +
                                 double(i * j) * corners[2] + double((3 - i) * j) * corners[3]) /
                                9.0;
  return patch;
}

// OpenSubdiv's Gregory basis numbers its 20 points per corner (P, E+, E-,
// F+, F-); this is where each lands in the Bézier grid.
BezierPatch bezierFromGregory(const std::array<glm::dvec3, 20>& cvs) {
  static constexpr int kBoundaryPoint[12] = {0, 1, 7, 5, 2, 6, 16, 12, 15, 17, 11, 10};
  static constexpr int kBoundarySlot[12] = {0, 1, 2, 3, 4, 7, 8, 11, 12, 13, 14, 15};
  static constexpr int kInteriorPrimary[4] = {3, 8, 13, 18};
  static constexpr int kInteriorAlternate[4] = {4, 9, 14, 19};
  static constexpr int kInteriorSlot[4] = {5, 6, 10, 9};
  BezierPatch patch;
  patch.gregory = true;
  for (int k = 0; k < 12; ++k) patch.points[kBoundarySlot[k]] = cvs[kBoundaryPoint[k]];
  for (int k = 0; k < 4; ++k) {
    patch.points[kInteriorSlot[k]] = cvs[kInteriorPrimary[k]];
    patch.alternates[k] = cvs[kInteriorAlternate[k]];
  }
  return patch;
}

// One patch of OpenSubdiv's (vertex or face-varying) in Bézier form, its
// control points `cvs` into `points`.
BezierPatch bezierFromPatch(Far::PatchDescriptor::Type type, Far::ConstIndexArray cvs,
                            const std::vector<OsdPoint>& points, unsigned boundaryMask) {
  auto gather = [&](auto& array) {
    for (std::size_t k = 0; k < array.size(); ++k) array[k] = points[std::size_t(cvs[int(k)])].p;
    return array;
  };
  if (type == Far::PatchDescriptor::QUADS) {
    std::array<glm::dvec3, 4> corners;
    return bezierFromBilinear(gather(corners));
  }
  if (type == Far::PatchDescriptor::GREGORY_BASIS) {
    std::array<glm::dvec3, 20> basis;
    return bezierFromGregory(gather(basis));
  }
  std::array<glm::dvec3, 16> bspline;
  return bezierFromBSpline(gather(bspline), boundaryMask);
}

// Sum_k w[k] points[cvs[k]], k < count, with derivatives in face parameters.
LimitPoint combine(const PatchInfo& info, const BezierPatch& bezier, const double* wP, const double* wDu,
                   const double* wDv, Far::ConstIndexArray cvs, int count, const std::vector<OsdPoint>& points,
                   double u, double v) {
  LimitPoint result;
  for (int k = 0; k < count; ++k) {
    const glm::dvec3& p = points[std::size_t(cvs[k])].p;
    result.position += wP[k] * p;
    result.du += wDu[k] * p;
    result.dv += wDv[k] * p;
  }
  // OpenSubdiv scales derivatives by 2^depth, also on the sub-faces of
  // non-quad faces, which start at depth 1 and so span 2^-(depth-1) of
  // their ptex face: there its derivatives are twice ours (the
  // finite-difference test holds this). Rescale to ptex face parameters.
  const double derivativeScale = 1.0 / (info.domain.size * static_cast<double>(1 << info.depth));
  result.du *= derivativeScale;
  result.dv *= derivativeScale;
  if (bezier.gregory) {
    // OpenSubdiv's Gregory derivatives freeze the rational interior
    // (see the header); differentiate the same patch exactly instead.
    const PatchDomain& domain = info.domain;
    BezierSample exact = evaluateBezierPatch(bezier, (u - domain.u0) / domain.size, (v - domain.v0) / domain.size);
    result.du = exact.du / domain.size;
    result.dv = exact.dv / domain.size;
  }
  return result;
}

// The authored normals at a bilinear patch's corners. On a quad face they are
// its vertices' own; a face split once has patches through a vertex, two edge
// midpoints and the centroid, whose normals are the normalized sums of the
// normals there, as the split interpolates positions. Which a corner is
// follows from its position (the refined points are exact averages).
std::array<glm::dvec3, 4> cornerNormals(const ControlCage& cage, int face, int first,
                                        const std::array<glm::dvec3, 4>& corners) {
  const int count = cage.faceVertexCounts[std::size_t(face)];
  auto position = [&](int k) { return cage.positions[std::size_t(cage.faceVertexIndices[std::size_t(first + k)])]; };
  auto normal = [&](int k) { return cage.faceVertexNormals[std::size_t(first + k)]; };
  // Candidates: each corner, each edge midpoint, the centroid.
  std::vector<std::pair<glm::dvec3, glm::dvec3>> candidates;
  glm::dvec3 centroid(0.0), centroidNormal(0.0);
  for (int k = 0; k < count; ++k) {
    const int next = (k + 1) % count;
    candidates.push_back({position(k), normal(k)});
    candidates.push_back({0.5 * (position(k) + position(next)), normal(k) + normal(next)});
    centroid += position(k) / double(count);
    centroidNormal += normal(k);
  }
  candidates.push_back({centroid, centroidNormal});
  std::array<glm::dvec3, 4> normals;
  for (int c = 0; c < 4; ++c) {
    const auto nearest = std::min_element(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
      return glm::distance(a.first, corners[std::size_t(c)]) < glm::distance(b.first, corners[std::size_t(c)]);
    });
    const double length = glm::length(nearest->second);
    normals[std::size_t(c)] = length > 0.0 ? nearest->second / length : glm::dvec3(0.0);
  }
  return normals;
}

}  // namespace

// Everything evaluation needs; the refiner is dropped once the patch table
// and the points exist.
struct SubdivisionSurface::Impl {
  std::unique_ptr<Far::PatchTable> patchTable;
  std::unique_ptr<Far::PatchMap> patchMap;
  std::vector<OsdPoint> points;  // refined levels, then local points
  std::vector<Far::PatchTable::PatchHandle> handles;
  std::vector<PatchInfo> patches;
  std::vector<BezierPatch> bezierPatches;
  std::vector<std::array<glm::dvec3, 4>> authoredNormals;  // per patch, or empty
  // Texture coordinates (u, v, 0): refined levels, then local points; and
  // per patch the face-varying patch as OpenSubdiv has it and in Bézier form.
  std::vector<OsdPoint> texcoordPoints;
  std::vector<Far::PatchDescriptor::Type> texcoordTypes;
  std::vector<BezierPatch> texcoordPatches;
  Aabb bounds;
  SurfaceStatistics statistics;
};

SubdivisionSurface::SubdivisionSurface(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SubdivisionSurface::SubdivisionSurface(SubdivisionSurface&&) noexcept = default;
SubdivisionSurface& SubdivisionSurface::operator=(SubdivisionSurface&&) noexcept = default;
SubdivisionSurface::~SubdivisionSurface() = default;

SubdivisionSurface SubdivisionSurface::create(const ControlCage& cage, const RefinementSettings& settings) {
  auto impl = std::make_unique<Impl>();
  const bool bilinear = settings.subdivision == Subdivision::None;
  const std::unique_ptr<Far::TopologyRefiner> refinerOwner = createRefiner(cage, settings.subdivision);
  Far::TopologyRefiner& refiner = *refinerOwner;

  // A bilinear quad is a patch as it stands; one level splits every other
  // face into quads.
  const int level = bilinear ? 1 : isolationLevelFor(cage, settings);
  Far::PatchTableFactory::Options options(level);
  options.SetEndCapType(settings.endCaps == EndCapBasis::Gregory
                            ? Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS
                            : Far::PatchTableFactory::Options::ENDCAP_BSPLINE_BASIS);
  // Infinitely sharp creases become boundary patches instead of being
  // isolated down to the maximum level.
  options.useInfSharpPatch = true;
  options.useSingleCreasePatch = false;
  options.generateVaryingTables = false;
  options.generateVaryingLocalPoints = false;
  options.SetPatchPrecision<double>();
  // Face-varying patches of the same kinds as the vertex ones (the legacy
  // option makes them all bilinear in the refined values).
  const bool withTexcoords = !cage.faceVertexTexcoords.empty();
  options.generateFVarTables = withTexcoords;
  options.generateFVarLegacyLinearPatches = false;
  options.SetFVarPatchPrecision<double>();
  refiner.RefineAdaptive(options.GetRefineAdaptiveOptions());
  impl->patchTable.reset(Far::PatchTableFactory::Create(refiner, options));
  const Far::PatchTable& table = *impl->patchTable;

  // Positions: cage, every refined level, then the end-cap local points.
  const int refinedCount = refiner.GetNumVerticesTotal();
  const int localCount = table.GetNumLocalPoints();
  impl->points.resize(static_cast<size_t>(refinedCount) + localCount);
  for (int v = 0; v < cage.vertexCount(); ++v) impl->points[v].p = cage.positions[v];
  Far::PrimvarRefinerReal<double> primvarRefiner(refiner);
  OsdPoint* source = impl->points.data();
  for (int l = 1; l < refiner.GetNumLevels(); ++l) {
    OsdPoint* destination = source + refiner.GetLevel(l - 1).GetNumVertices();
    primvarRefiner.Interpolate(l, source, destination);
    source = destination;
  }
  if (localCount > 0)
    table.GetLocalPointStencilTable<double>()->UpdateValues(impl->points.data(), impl->points.data() + refinedCount);

  if (withTexcoords) {
    const int refinedValues = refiner.GetNumFVarValuesTotal(0);
    const int localValues = table.GetNumLocalPointsFaceVarying(0);
    impl->texcoordPoints.resize(std::size_t(refinedValues) + std::size_t(localValues));
    for (std::size_t t = 0; t < cage.texcoords.size(); ++t) impl->texcoordPoints[t].p = glm::dvec3(cage.texcoords[t], 0.0);
    OsdPoint* values = impl->texcoordPoints.data();
    for (int l = 1; l < refiner.GetNumLevels(); ++l) {
      OsdPoint* next = values + refiner.GetLevel(l - 1).GetNumFVarValues(0);
      primvarRefiner.InterpolateFaceVarying(l, values, next, 0);
      values = next;
    }
    if (localValues > 0)
      table.GetLocalPointFaceVaryingStencilTable<double>(0)->UpdateValues(impl->texcoordPoints.data(),
                                                                         impl->texcoordPoints.data() + refinedValues);
  }

  impl->patchMap = std::make_unique<Far::PatchMap>(table);

  Far::PtexIndices ptex(refiner);
  std::vector<int> coarseFaceOfPtex(ptex.GetNumFaces());
  for (int face = 0; face < cage.faceCount(); ++face) {
    int first = ptex.GetFaceId(face);
    int count = cage.faceVertexCounts[face] == 4 ? 1 : cage.faceVertexCounts[face];
    for (int k = 0; k < count; ++k) coarseFaceOfPtex[first + k] = face;
  }

  SurfaceStatistics& stats = impl->statistics;
  const bool withNormals = bilinear && !cage.faceVertexNormals.empty();
  if (withNormals && cage.faceVertexNormals.size() != cage.faceVertexIndices.size())
    throw InputError(cage.source, 0, "authored normals",
                     std::to_string(cage.faceVertexNormals.size()) + " normals for " +
                         std::to_string(cage.faceVertexIndices.size()) + " face corners");
  std::vector<int> faceStarts;
  for (int face = 0, first = 0; face < cage.faceCount(); first += cage.faceVertexCounts[std::size_t(face++)])
    faceStarts.push_back(first);
  int patchIndex = 0;
  for (int array = 0; array < table.GetNumPatchArrays(); ++array) {
    const Far::PatchDescriptor descriptor = table.GetPatchArrayDescriptor(array);
    const bool quads = descriptor.GetType() == Far::PatchDescriptor::QUADS;
    const bool gregory = descriptor.GetType() == Far::PatchDescriptor::GREGORY_BASIS;
    const int cvCount = descriptor.GetNumControlVertices();
    for (int j = 0; j < table.GetNumPatches(array); ++j, ++patchIndex) {
      Far::PatchTable::PatchHandle handle;
      handle.arrayIndex = array;
      handle.patchIndex = patchIndex;
      handle.vertIndex = j * cvCount;
      impl->handles.push_back(handle);

      const Far::PatchParam param = table.GetPatchParam(array, j);
      const Far::ConstIndexArray cvs = table.GetPatchVertices(array, j);
      PatchInfo info;
      info.ptexFace = param.GetFaceId();
      info.coarseFace = coarseFaceOfPtex[info.ptexFace];
      info.domain.size = param.GetParamFraction();
      info.domain.u0 = param.GetU() * info.domain.size;
      info.domain.v0 = param.GetV() * info.domain.size;
      info.depth = param.GetDepth();
      info.boundaryMask = param.GetBoundary();
      info.transitionMask = param.GetTransition();
      info.gregory = gregory;
      impl->patches.push_back(info);

      const BezierPatch bezier = bezierFromPatch(descriptor.GetType(), cvs, impl->points, info.boundaryMask);
      if (quads) {
        std::array<glm::dvec3, 4> points;
        for (int k = 0; k < 4; ++k) points[k] = impl->points[cvs[k]].p;
        if (withNormals)
          impl->authoredNormals.push_back(
              cornerNormals(cage, info.coarseFace, faceStarts[std::size_t(info.coarseFace)], points));
        ++stats.regularPatches;
      } else if (gregory) {
        ++stats.endCapPatches;
      } else {
        // B-spline end caps share the regular patch type.
        if (param.IsRegular())
          ++stats.regularPatches;
        else
          ++stats.endCapPatches;
      }
      for (const glm::dvec3& p : bezier.points) impl->bounds.extend(p);
      if (bezier.gregory)
        for (const glm::dvec3& p : bezier.alternates) impl->bounds.extend(p);
      impl->bezierPatches.push_back(bezier);
      if (withTexcoords) {
        const Far::PatchParam texcoordParam = table.GetPatchFVarPatchParam(array, j, 0);
        const Far::PatchDescriptor::Type type = (texcoordParam.IsRegular() ? table.GetFVarPatchDescriptorRegular(0)
                                                                           : table.GetFVarPatchDescriptorIrregular(0))
                                                    .GetType();
        impl->texcoordTypes.push_back(type);
        impl->texcoordPatches.push_back(bezierFromPatch(type, table.GetPatchFVarValues(array, j, 0),
                                                        impl->texcoordPoints, texcoordParam.GetBoundary()));
      }
    }
  }

  stats.subdivision = settings.subdivision;
  stats.isolationLevel = bilinear ? 0 : level;
  stats.cageFaces = cage.faceCount();
  stats.ptexFaces = ptex.GetNumFaces();
  stats.refinedVertices = refinedCount;
  stats.localPoints = localCount;
  size_t stencilBytes = 0;
  if (const auto* stencils = table.GetLocalPointStencilTable<double>()) {
    stencilBytes = stencils->GetControlIndices().size() * sizeof(Far::Index) +
                   stencils->GetWeights().size() * sizeof(double) +
                   static_cast<size_t>(stencils->GetNumStencils()) * 2 * sizeof(int);
  }
  stats.openSubdivBytes = static_cast<size_t>(table.GetNumControlVerticesTotal()) * sizeof(Far::Index) +
                          static_cast<size_t>(table.GetNumPatchesTotal()) * sizeof(Far::PatchParam) +
                          impl->points.size() * sizeof(OsdPoint) + stencilBytes;
  return SubdivisionSurface(std::move(impl));
}

int SubdivisionSurface::patchCount() const { return static_cast<int>(impl_->patches.size()); }
const PatchInfo& SubdivisionSurface::patch(int index) const { return impl_->patches.at(index); }
const BezierPatch& SubdivisionSurface::bezierPatch(int index) const { return impl_->bezierPatches.at(index); }
const std::array<glm::dvec3, 4>* SubdivisionSurface::authoredNormals(int index) const {
  return impl_->authoredNormals.empty() ? nullptr : &impl_->authoredNormals.at(std::size_t(index));
}
const Aabb& SubdivisionSurface::bounds() const { return impl_->bounds; }
const SurfaceStatistics& SubdivisionSurface::statistics() const { return impl_->statistics; }

LimitPoint SubdivisionSurface::evaluatePatch(int index, double u, double v) const {
  const Far::PatchTable::PatchHandle& handle = impl_->handles.at(std::size_t(index));
  double wP[20], wDu[20], wDv[20];
  impl_->patchTable->EvaluateBasis(handle, u, v, wP, wDu, wDv);
  const Far::ConstIndexArray cvs = impl_->patchTable->GetPatchVertices(handle);
  return combine(impl_->patches[std::size_t(index)], impl_->bezierPatches[std::size_t(index)], wP, wDu, wDv, cvs,
                 cvs.size(), impl_->points, u, v);
}

bool SubdivisionSurface::hasTexcoords() const { return !impl_->texcoordPatches.empty(); }

const BezierPatch* SubdivisionSurface::texcoordPatch(int index) const {
  return hasTexcoords() ? &impl_->texcoordPatches.at(std::size_t(index)) : nullptr;
}

LimitTexcoord SubdivisionSurface::evaluateTexcoord(int index, double u, double v) const {
  if (!hasTexcoords()) return {};
  const Far::PatchTable::PatchHandle& handle = impl_->handles.at(std::size_t(index));
  double wP[20], wDu[20], wDv[20];
  impl_->patchTable->EvaluateBasisFaceVarying(handle, u, v, wP, wDu, wDv, nullptr, nullptr, nullptr, 0);
  const Far::PatchDescriptor::Type type = impl_->texcoordTypes[std::size_t(index)];
  const LimitPoint sum =
      combine(impl_->patches[std::size_t(index)], impl_->texcoordPatches[std::size_t(index)], wP, wDu, wDv,
              impl_->patchTable->GetPatchFVarValues(handle, 0), Far::PatchDescriptor::GetNumControlVertices(type),
              impl_->texcoordPoints, u, v);
  return {glm::dvec2(sum.position), glm::dvec2(sum.du), glm::dvec2(sum.dv)};
}

std::optional<int> SubdivisionSurface::findPatch(int ptexFace, double u, double v) const {
  const Far::PatchTable::PatchHandle* handle = impl_->patchMap->FindPatch(ptexFace, u, v);
  if (!handle) return std::nullopt;
  return handle->patchIndex;
}

std::optional<LimitPoint> SubdivisionSurface::evaluateFace(int ptexFace, double u, double v) const {
  std::optional<int> index = findPatch(ptexFace, u, v);
  if (!index) return std::nullopt;
  return evaluatePatch(*index, u, v);
}

std::string describe(const SurfaceStatistics& stats) {
  std::ostringstream out;
  out << stats.cageFaces << " cage faces (" << stats.ptexFaces << " ptex), ";
  if (stats.subdivision == Subdivision::None)
    out << "as authored: " << stats.regularPatches << " bilinear patches, ";
  else
    out << "isolation level " << stats.isolationLevel << ": " << stats.regularPatches + stats.endCapPatches
        << " patches (" << stats.regularPatches << " regular, " << stats.endCapPatches << " end caps), ";
  out << stats.refinedVertices << " refined + " << stats.localPoints << " local points, "
      << (stats.openSubdivBytes + 512) / 1024 << " KiB in OpenSubdiv tables";
  return out.str();
}

}  // namespace facet::scene
