#include "scenes/cage_topology.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <vector>

namespace facet::scene {
namespace {

std::uint64_t edgeKey(int from, int to) { return (std::uint64_t(std::uint32_t(from)) << 32) | std::uint32_t(to); }

int findRoot(std::vector<int>& parent, int i) {
  while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
  return i;
}

// The faces of a cage whose every directed edge appears once and its
// reverse once: which face each directed edge bounds, and each face's
// connected piece (a root face per piece).
struct PairedEdges {
  std::unordered_map<std::uint64_t, int> faceOfEdge;
  std::vector<int> piece;  // per face
};

std::optional<PairedEdges> pairEdges(const ControlCage& cage) {
  if (!cage.holes.empty() || cage.faceCount() == 0) return std::nullopt;
  PairedEdges paired;
  std::size_t first = 0;
  for (int f = 0; f < cage.faceCount(); ++f) {
    const int count = cage.faceVertexCounts[std::size_t(f)];
    const auto begin = cage.faceVertexIndices.begin() + std::ptrdiff_t(first);
    std::vector<int> corners(begin, begin + count);
    std::sort(corners.begin(), corners.end());
    if (std::adjacent_find(corners.begin(), corners.end()) != corners.end()) return std::nullopt;
    for (int k = 0; k < count; ++k) {
      const int a = cage.faceVertexIndices[first + std::size_t(k)];
      const int b = cage.faceVertexIndices[first + std::size_t((k + 1) % count)];
      if (!paired.faceOfEdge.emplace(edgeKey(a, b), f).second) return std::nullopt;
    }
    first += std::size_t(count);
  }
  std::vector<int> parent(std::size_t(cage.faceCount()));
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [key, face] : paired.faceOfEdge) {
    const auto twin = paired.faceOfEdge.find((key << 32) | (key >> 32));
    if (twin == paired.faceOfEdge.end()) return std::nullopt;
    parent[std::size_t(findRoot(parent, face))] = findRoot(parent, twin->second);
  }
  paired.piece.resize(parent.size());
  for (int f = 0; f < cage.faceCount(); ++f) paired.piece[std::size_t(f)] = findRoot(parent, f);
  return paired;
}

}  // namespace

bool closesIntoSphere(const ControlCage& cage) {
  const std::optional<PairedEdges> paired = pairEdges(cage);
  if (!paired ||
      std::any_of(paired->piece.begin(), paired->piece.end(), [&](int root) { return root != paired->piece.front(); }))
    return false;
  std::vector<char> used(cage.positions.size(), 0);
  for (int index : cage.faceVertexIndices) used[std::size_t(index)] = 1;
  const auto vertices = std::ptrdiff_t(std::count(used.begin(), used.end(), 1));
  const auto edges = std::ptrdiff_t(paired->faceOfEdge.size() / 2);
  return vertices - edges + cage.faceCount() == 2;
}

bool enclosesSolid(const ControlCage& cage) {
  const std::optional<PairedEdges> paired = pairEdges(cage);
  if (!paired) return false;
  // Six times each piece's signed volume: the divergence theorem over its
  // faces, each a fan of triangles about its first corner.
  std::unordered_map<int, double> volume;
  std::size_t first = 0;
  for (int f = 0; f < cage.faceCount(); ++f) {
    const int count = cage.faceVertexCounts[std::size_t(f)];
    const glm::dvec3& a = cage.positions[std::size_t(cage.faceVertexIndices[first])];
    double& piece = volume[paired->piece[std::size_t(f)]];
    for (int k = 1; k + 1 < count; ++k)
      piece += glm::dot(a, glm::cross(cage.positions[std::size_t(cage.faceVertexIndices[first + std::size_t(k)])],
                                      cage.positions[std::size_t(cage.faceVertexIndices[first + std::size_t(k + 1)])]));
    first += std::size_t(count);
  }
  return std::all_of(volume.begin(), volume.end(), [](const auto& piece) { return piece.second > 0.0; });
}

}  // namespace facet::scene
