// SubdivisionSurface::create: a cage refined into OpenSubdiv's patch table,
// its points computed, and every patch kept in Bézier form with statistics.
#include "scenes/subdivision_surface.h"
#include "scenes/subdivision_internal.h"

#include "scenes/input_error.h"

#include <glm/geometric.hpp>

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>

#include <algorithm>
#include <sstream>

namespace facet::scene {
namespace {

// Which of a face's corners (offsets from its first) each corner of a
// bilinear patch of it stands on: on a quad face its own vertex; a face
// split once has patches through a vertex, two edge midpoints and the
// centroid, whose attributes are the sums of those there, as the split
// interpolates positions. Which a corner is follows from its position (the
// refined points are exact averages).
std::array<std::vector<int>, 4> patchCornerSources(const ControlCage& cage, int face, int first,
                                                   const std::array<glm::dvec3, 4>& corners) {
  const int count = cage.faceVertexCounts[std::size_t(face)];
  auto position = [&](int k) { return cage.positions[std::size_t(cage.faceVertexIndices[std::size_t(first + k)])]; };
  // Candidates: each corner, each edge midpoint, the centroid.
  std::vector<std::pair<glm::dvec3, std::vector<int>>> candidates;
  glm::dvec3 centroid(0.0);
  std::vector<int> all;
  for (int k = 0; k < count; ++k) {
    const int next = (k + 1) % count;
    candidates.push_back({position(k), {k}});
    candidates.push_back({0.5 * (position(k) + position(next)), {k, next}});
    centroid += position(k) / double(count);
    all.push_back(k);
  }
  candidates.push_back({centroid, all});
  std::array<std::vector<int>, 4> sources;
  for (int c = 0; c < 4; ++c) {
    const auto nearest = std::min_element(candidates.begin(), candidates.end(), [&](const auto& a, const auto& b) {
      return glm::distance(a.first, corners[std::size_t(c)]) < glm::distance(b.first, corners[std::size_t(c)]);
    });
    sources[std::size_t(c)] = nearest->second;
  }
  return sources;
}

// The sum of a per-corner attribute over each patch corner's sources.
template <class T>
std::array<T, 4> summedAtCorners(const std::vector<T>& perCorner, int first,
                                 const std::array<std::vector<int>, 4>& sources) {
  std::array<T, 4> sums{};
  for (std::size_t c = 0; c < 4; ++c)
    for (int k : sources[c]) sums[c] += perCorner[std::size_t(first + k)];
  return sums;
}

// The authored normals at a bilinear patch's corners: the sums normalized.
std::array<glm::dvec3, 4> cornerNormals(const ControlCage& cage, int first,
                                        const std::array<std::vector<int>, 4>& sources) {
  std::array<glm::dvec3, 4> normals = summedAtCorners(cage.faceVertexNormals, first, sources);
  for (glm::dvec3& n : normals) {
    const double length = glm::length(n);
    n = length > 0.0 ? n / length : glm::dvec3(0.0);
  }
  return normals;
}

// The mesh's tangents at a bilinear patch's corners: the means of the
// directions, unnormalized, so that the patch interpolates a triangle's
// corner tangents exactly as the baker's barycentric interpolation did (the
// patch's corners are the corresponding means of the positions); and the
// sign most of the corners there carry.
std::array<glm::dvec4, 4> cornerTangents(const ControlCage& cage, int first,
                                         const std::array<std::vector<int>, 4>& sources) {
  std::array<glm::dvec4, 4> tangents = summedAtCorners(cage.faceVertexTangents, first, sources);
  for (std::size_t c = 0; c < 4; ++c) {
    const glm::dvec4 sum = tangents[c];
    tangents[c] = glm::dvec4(glm::dvec3(sum) / double(sources[c].size()), sum.w < 0.0 ? -1.0 : 1.0);
  }
  return tangents;
}

// The patch table's options: patches isolated to `level`, end caps of the
// settings' basis, and face-varying patches where the cage has channels.
Far::PatchTableFactory::Options patchTableOptions(const RefinementSettings& settings, int level, bool faceVarying) {
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
  options.generateFVarTables = faceVarying;
  options.generateFVarLegacyLinearPatches = false;
  options.SetFVarPatchPrecision<double>();
  return options;
}

// Positions: cage, every refined level, then the end-cap local points.
std::vector<detail::OsdPoint> refinedPositions(const ControlCage& cage, const Far::TopologyRefiner& refiner,
                                               const Far::PatchTable& table) {
  const int refinedCount = refiner.GetNumVerticesTotal();
  std::vector<detail::OsdPoint> points(static_cast<size_t>(refinedCount) + table.GetNumLocalPoints());
  for (int v = 0; v < cage.vertexCount(); ++v) points[v].p = cage.positions[v];
  Far::PrimvarRefinerReal<double> primvarRefiner(refiner);
  detail::OsdPoint* source = points.data();
  for (int l = 1; l < refiner.GetNumLevels(); ++l) {
    detail::OsdPoint* destination = source + refiner.GetLevel(l - 1).GetNumVertices();
    primvarRefiner.Interpolate(l, source, destination);
    source = destination;
  }
  if (table.GetNumLocalPoints() > 0)
    table.GetLocalPointStencilTable<double>()->UpdateValues(points.data(), points.data() + refinedCount);
  return points;
}

// A face-varying channel's values, in the same order as refinedPositions'.
std::vector<detail::OsdPoint> refinedChannelValues(const std::vector<glm::dvec3>& cageValues,
                                                   const Far::TopologyRefiner& refiner, const Far::PatchTable& table,
                                                   int fvar) {
  const int refinedValues = refiner.GetNumFVarValuesTotal(fvar);
  const int localValues = table.GetNumLocalPointsFaceVarying(fvar);
  std::vector<detail::OsdPoint> points(std::size_t(refinedValues) + std::size_t(localValues));
  for (std::size_t t = 0; t < cageValues.size(); ++t) points[t].p = cageValues[t];
  Far::PrimvarRefinerReal<double> primvarRefiner(refiner);
  detail::OsdPoint* values = points.data();
  for (int l = 1; l < refiner.GetNumLevels(); ++l) {
    detail::OsdPoint* next = values + refiner.GetLevel(l - 1).GetNumFVarValues(fvar);
    primvarRefiner.InterpolateFaceVarying(l, values, next, fvar);
    values = next;
  }
  if (localValues > 0)
    table.GetLocalPointFaceVaryingStencilTable<double>(fvar)->UpdateValues(points.data(),
                                                                           points.data() + refinedValues);
  return points;
}

// The cage face of each ptex face: a quad is one, an n-gon n.
std::vector<int> coarseFacesOfPtexFaces(const ControlCage& cage, const Far::PtexIndices& ptex) {
  std::vector<int> coarseFaceOfPtex(ptex.GetNumFaces());
  for (int face = 0; face < cage.faceCount(); ++face) {
    int first = ptex.GetFaceId(face);
    int count = cage.faceVertexCounts[face] == 4 ? 1 : cage.faceVertexCounts[face];
    for (int k = 0; k < count; ++k) coarseFaceOfPtex[first + k] = face;
  }
  return coarseFaceOfPtex;
}

// Where each cage face's corners start in faceVertexIndices.
std::vector<int> faceStarts(const ControlCage& cage) {
  std::vector<int> starts;
  for (int face = 0, first = 0; face < cage.faceCount(); first += cage.faceVertexCounts[std::size_t(face++)])
    starts.push_back(first);
  return starts;
}

PatchInfo patchInfo(const Far::PatchParam& param, const std::vector<int>& coarseFaceOfPtex, bool gregory) {
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
  return info;
}

void countPatch(SurfaceStatistics& stats, const Far::PatchDescriptor& descriptor, const Far::PatchParam& param) {
  if (descriptor.GetType() == Far::PatchDescriptor::QUADS) {
    ++stats.regularPatches;
  } else if (descriptor.GetType() == Far::PatchDescriptor::GREGORY_BASIS) {
    ++stats.endCapPatches;
  } else {
    // B-spline end caps share the regular patch type.
    if (param.IsRegular())
      ++stats.regularPatches;
    else
      ++stats.endCapPatches;
  }
}

void extendBounds(Aabb& bounds, const BezierPatch& bezier) {
  for (const glm::dvec3& p : bezier.points) bounds.extend(p);
  if (bezier.gregory)
    for (const glm::dvec3& p : bezier.alternates) bounds.extend(p);
}

// The bytes OpenSubdiv holds for the surface: patch vertices and parameters,
// the refined and local points, and the local points' stencils.
size_t openSubdivBytes(const Far::PatchTable& table, std::size_t pointCount) {
  size_t stencilBytes = 0;
  if (const auto* stencils = table.GetLocalPointStencilTable<double>()) {
    stencilBytes = stencils->GetControlIndices().size() * sizeof(Far::Index) +
                   stencils->GetWeights().size() * sizeof(double) +
                   static_cast<size_t>(stencils->GetNumStencils()) * 2 * sizeof(int);
  }
  return static_cast<size_t>(table.GetNumControlVerticesTotal()) * sizeof(Far::Index) +
         static_cast<size_t>(table.GetNumPatchesTotal()) * sizeof(Far::PatchParam) +
         pointCount * sizeof(detail::OsdPoint) + stencilBytes;
}

}  // namespace

SubdivisionSurface::SubdivisionSurface(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SubdivisionSurface::SubdivisionSurface(SubdivisionSurface&&) noexcept = default;
SubdivisionSurface& SubdivisionSurface::operator=(SubdivisionSurface&&) noexcept = default;
SubdivisionSurface::~SubdivisionSurface() = default;

SubdivisionSurface SubdivisionSurface::create(const ControlCage& cage, const RefinementSettings& settings) {
  auto impl = std::make_unique<Impl>();
  const bool bilinear = settings.subdivision == Subdivision::None;
  const std::unique_ptr<Far::TopologyRefiner> refinerOwner = detail::createRefiner(cage, settings.subdivision);
  Far::TopologyRefiner& refiner = *refinerOwner;

  // A bilinear quad is a patch as it stands; one level splits every other
  // face into quads.
  const int level = bilinear ? 1 : detail::isolationLevelFor(cage, settings);
  int fvarChannels = 0;
  for (int c = 0; c < kChannelCount; ++c)
    if (!detail::channelValues(cage, Channel(c)).corners.empty()) impl->channels[std::size_t(c)].fvar = fvarChannels++;
  const Far::PatchTableFactory::Options options = patchTableOptions(settings, level, fvarChannels > 0);
  refiner.RefineAdaptive(options.GetRefineAdaptiveOptions());
  impl->patchTable.reset(Far::PatchTableFactory::Create(refiner, options));
  const Far::PatchTable& table = *impl->patchTable;

  impl->points = refinedPositions(cage, refiner, table);
  for (int c = 0; c < kChannelCount; ++c) {
    SubdivisionSurface::Impl::FaceVarying& channel = impl->channels[std::size_t(c)];
    if (channel.fvar >= 0)
      channel.points =
          refinedChannelValues(detail::channelValues(cage, Channel(c)).values, refiner, table, channel.fvar);
  }

  impl->patchMap = std::make_unique<Far::PatchMap>(table);

  Far::PtexIndices ptex(refiner);
  const std::vector<int> coarseFaceOfPtex = coarseFacesOfPtexFaces(cage, ptex);

  SurfaceStatistics& stats = impl->statistics;
  const bool withNormals = bilinear && !cage.faceVertexNormals.empty();
  if (withNormals && cage.faceVertexNormals.size() != cage.faceVertexIndices.size())
    throw InputError(cage.source, 0, "authored normals",
                     std::to_string(cage.faceVertexNormals.size()) + " normals for " +
                         std::to_string(cage.faceVertexIndices.size()) + " face corners");
  const bool withTangents = withNormals && !cage.faceVertexTangents.empty();
  if (withTangents && cage.faceVertexTangents.size() != cage.faceVertexIndices.size())
    throw InputError(cage.source, 0, "mesh tangents",
                     std::to_string(cage.faceVertexTangents.size()) + " tangents for " +
                         std::to_string(cage.faceVertexIndices.size()) + " face corners");
  const std::vector<int> starts = faceStarts(cage);
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
      const PatchInfo info = patchInfo(param, coarseFaceOfPtex, gregory);
      impl->patches.push_back(info);

      const BezierPatch bezier = detail::bezierFromPatch(descriptor.GetType(), cvs, impl->points, info.boundaryMask);
      if (quads && withNormals) {
        std::array<glm::dvec3, 4> points;
        for (int k = 0; k < 4; ++k) points[k] = impl->points[cvs[k]].p;
        const int first = starts[std::size_t(info.coarseFace)];
        const std::array<std::vector<int>, 4> sources = patchCornerSources(cage, info.coarseFace, first, points);
        impl->authoredNormals.push_back(cornerNormals(cage, first, sources));
        if (withTangents) impl->authoredTangents.push_back(cornerTangents(cage, first, sources));
      }
      countPatch(stats, descriptor, param);
      extendBounds(impl->bounds, bezier);
      impl->bezierPatches.push_back(bezier);
      for (SubdivisionSurface::Impl::FaceVarying& channel : impl->channels) {
        if (channel.fvar < 0) continue;
        const Far::PatchParam fvarParam = table.GetPatchFVarPatchParam(array, j, channel.fvar);
        const Far::PatchDescriptor::Type type =
            (fvarParam.IsRegular() ? table.GetFVarPatchDescriptorRegular(channel.fvar)
                                   : table.GetFVarPatchDescriptorIrregular(channel.fvar))
                .GetType();
        channel.types.push_back(type);
        channel.patches.push_back(detail::bezierFromPatch(type, table.GetPatchFVarValues(array, j, channel.fvar),
                                                          channel.points, fvarParam.GetBoundary()));
      }
    }
  }

  stats.subdivision = settings.subdivision;
  stats.isolationLevel = bilinear ? 0 : level;
  stats.cageFaces = cage.faceCount();
  stats.ptexFaces = ptex.GetNumFaces();
  stats.refinedVertices = refiner.GetNumVerticesTotal();
  stats.localPoints = table.GetNumLocalPoints();
  stats.openSubdivBytes = openSubdivBytes(table, impl->points.size());
  return SubdivisionSurface(std::move(impl));
}

int SubdivisionSurface::patchCount() const { return static_cast<int>(impl_->patches.size()); }
const PatchInfo& SubdivisionSurface::patch(int index) const { return impl_->patches.at(index); }
const BezierPatch& SubdivisionSurface::bezierPatch(int index) const { return impl_->bezierPatches.at(index); }
const std::array<glm::dvec3, 4>* SubdivisionSurface::authoredNormals(int index) const {
  return impl_->authoredNormals.empty() ? nullptr : &impl_->authoredNormals.at(std::size_t(index));
}
const std::array<glm::dvec4, 4>* SubdivisionSurface::authoredTangents(int index) const {
  return impl_->authoredTangents.empty() ? nullptr : &impl_->authoredTangents.at(std::size_t(index));
}
bool SubdivisionSurface::hasAuthoredTangents() const { return !impl_->authoredTangents.empty(); }
const Aabb& SubdivisionSurface::bounds() const { return impl_->bounds; }
const SurfaceStatistics& SubdivisionSurface::statistics() const { return impl_->statistics; }

bool SubdivisionSurface::hasChannel(Channel channel) const { return impl_->channels[std::size_t(channel)].fvar >= 0; }

const BezierPatch* SubdivisionSurface::channelPatch(Channel channel, int index) const {
  return hasChannel(channel) ? &impl_->channels[std::size_t(channel)].patches.at(std::size_t(index)) : nullptr;
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
