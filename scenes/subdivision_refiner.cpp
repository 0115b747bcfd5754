// The control cage checked against the rules OpenSubdiv trusts its input to
// keep, then turned into OpenSubdiv's topology refiner.
#include "scenes/subdivision_internal.h"

#include "scenes/input_error.h"

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace facet::scene::detail {

namespace Sdc = OpenSubdiv::Sdc;

namespace {

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

void validateChannel(const ControlCage& cage, const ChannelValues& channel) {
  auto fail = [&cage](const std::string& rule, const std::string& detail) {
    throw InputError(cage.source, 0, rule, detail);
  };
  const std::string name = channel.name;
  if (channel.corners.empty()) {
    if (!channel.values.empty()) fail(name, "values given, but no face corner uses them");
    return;
  }
  if (channel.corners.size() != cage.faceVertexIndices.size())
    fail(name, std::to_string(channel.corners.size()) + " indices for " +
                   std::to_string(cage.faceVertexIndices.size()) + " face corners");
  for (int index : channel.corners)
    if (index < 0 || index >= int(channel.values.size()))
      fail("index out of range", name + " " + std::to_string(index) + " of " + std::to_string(channel.values.size()));
  for (const glm::dvec3& t : channel.values)
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z))
      fail("non-finite value", "a value of the " + name + " is NaN or infinite");
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
  for (int c = 0; c < kChannelCount; ++c) validateChannel(cage, channelValues(cage, Channel(c)));
}

}  // namespace

ChannelValues channelValues(const ControlCage& cage, Channel channel) {
  std::vector<glm::dvec3> values;
  switch (channel) {
    case Channel::Texcoord0:
      for (const glm::dvec2& t : cage.texcoords) values.push_back(glm::dvec3(t, 0.0));
      return {"texture coordinates", std::move(values), cage.faceVertexTexcoords};
    case Channel::Texcoord1:
      for (const glm::dvec2& t : cage.texcoords1) values.push_back(glm::dvec3(t, 0.0));
      return {"second texture coordinates", std::move(values), cage.faceVertexTexcoords1};
    case Channel::Color:
      break;
  }
  return {"vertex colours", cage.colors, cage.faceVertexColors};
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
  // The channels the cage has, in Channel's order (SubdivisionSurface::Impl).
  std::vector<Far::TopologyDescriptor::FVarChannel> channels;
  for (int c = 0; c < kChannelCount; ++c) {
    const ChannelValues channel = channelValues(cage, Channel(c));
    if (channel.corners.empty()) continue;
    channels.emplace_back();
    channels.back().numValues = int(channel.values.size());
    channels.back().valueIndices = channel.corners.data();
  }
  descriptor.numFVarChannels = int(channels.size());
  descriptor.fvarChannels = channels.empty() ? nullptr : channels.data();

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

}  // namespace facet::scene::detail
