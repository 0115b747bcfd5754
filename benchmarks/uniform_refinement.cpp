#include "benchmarks/uniform_refinement.h"

#include <glm/vec3.hpp>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace facet::benchmarks {
namespace {

using scene::ControlCage;

struct Vertex {
  glm::dvec3 p{0.0};
  void Clear() { p = glm::dvec3(0.0); }
  void AddWithWeight(const Vertex& src, float weight) { p += double(weight) * src.p; }
};

}  // namespace

ControlCage refineUniformly(const ControlCage& cage, int levels) {
  namespace Far = OpenSubdiv::Far;
  namespace Sdc = OpenSubdiv::Sdc;
  if (!cage.creases.empty() || !cage.corners.empty() || !cage.holes.empty())
    throw std::runtime_error("refineUniformly: cages with creases, corners or holes are not supported");
  Far::TopologyDescriptor descriptor;
  descriptor.numVertices = cage.vertexCount();
  descriptor.numFaces = cage.faceCount();
  descriptor.numVertsPerFace = cage.faceVertexCounts.data();
  descriptor.vertIndicesPerFace = cage.faceVertexIndices.data();
  Sdc::Options options;
  switch (cage.options.boundary) {
    case facet::scene::BoundaryInterpolation::None:
      options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
      break;
    case facet::scene::BoundaryInterpolation::EdgeOnly:
      options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
      break;
    case facet::scene::BoundaryInterpolation::EdgeAndCorner:
      options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
      break;
  }
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(descriptor, Factory::Options(Sdc::SCHEME_CATMARK, options)));
  if (!refiner) throw std::runtime_error("refineUniformly: OpenSubdiv rejected " + cage.source);
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));

  std::vector<Vertex> current(cage.positions.size());
  for (std::size_t i = 0; i < current.size(); ++i) current[i].p = cage.positions[i];
  Far::PrimvarRefiner primvar(*refiner);
  for (int level = 1; level <= levels; ++level) {
    std::vector<Vertex> next(std::size_t(refiner->GetLevel(level).GetNumVertices()));
    Vertex* destination = next.data();
    primvar.Interpolate(level, current.data(), destination);
    current = std::move(next);
  }

  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  ControlCage out;
  out.source = cage.source + " (uniform level " + std::to_string(levels) + ")";
  out.options = cage.options;
  for (const Vertex& v : current) out.positions.push_back(v.p);
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    out.faceVertexCounts.push_back(vertices.size());
    for (int i = 0; i < vertices.size(); ++i) out.faceVertexIndices.push_back(vertices[i]);
  }
  return out;
}

}  // namespace facet::benchmarks
