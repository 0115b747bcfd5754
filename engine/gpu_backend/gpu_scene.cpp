#include "engine/gpu_backend/gpu_scene.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "engine/gpu/gpu.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

// Float bounds that still contain the double ones.
float roundDown(double value) {
  const float f = float(value);
  return double(f) > value ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float roundUp(double value) {
  const float f = float(value);
  return double(f) < value ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

std::uint32_t bits(float value) { return std::bit_cast<std::uint32_t>(value); }

// Appends an empty node (every slot EMPTY) and returns its index.
std::uint32_t appendNode(std::vector<Texel>& texels) {
  const std::uint32_t index = std::uint32_t(texels.size() / layout::FACET_BVH4_TEXELS);
  texels.resize(texels.size() + layout::FACET_BVH4_TEXELS, Texel{0, 0, 0, 0});
  texels[std::size_t(index) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES] =
      Texel{layout::FACET_BVH4_EMPTY, layout::FACET_BVH4_EMPTY, layout::FACET_BVH4_EMPTY, layout::FACET_BVH4_EMPTY};
  return index;
}

// Child `slot` of `node`: its box, rebased on `origin`, grown by `margin` and
// rounded outwards, and its reference.
void writeChild(std::vector<Texel>& texels, std::uint32_t node, std::size_t slot, const scene::Aabb& bounds,
                std::uint32_t reference, const glm::dvec3& origin, double margin) {
  const std::size_t base = std::size_t(node) * layout::FACET_BVH4_TEXELS;
  for (int axis = 0; axis < 3; ++axis) {
    texels[base + 2 * std::size_t(axis)][slot] = bits(roundDown(bounds.lo[axis] - origin[axis] - margin));
    texels[base + 2 * std::size_t(axis) + 1][slot] = bits(roundUp(bounds.hi[axis] - origin[axis] + margin));
  }
  texels[base + layout::FACET_BVH4_REFERENCES][slot] = reference;
}

// A wide node's child while it is being chosen: a node of the binary patch
// BVH, or one patch (its slot in leaf order).
struct Candidate {
  bool isPatch = false;
  int index = 0;
  scene::Aabb bounds;
};

// Collapses one object's binary patch BVH into 4-wide nodes: each node takes
// the binary subtree's largest boxes as children until it has four (the
// usual collapse, as in Embree's BVH4 builders). Patch children refer to
// quadtree roots, relative to the object's first quadtree node until
// packScene() knows where the quadtrees start.
class Collapse {
 public:
  Collapse(const scene::PatchBvh& bvh, const std::vector<scene::Aabb>& patchBounds, const glm::dvec3& origin,
           double margin, std::uint32_t quadtreeNodes, std::vector<Texel>& texels)
      : bvh_(bvh), patchBounds_(patchBounds), origin_(origin), margin_(margin), quadtreeNodes_(quadtreeNodes),
        texels_(texels) {}

  // Returns the root's node index.
  std::uint32_t run() {
    if (bvh_.nodes().empty()) return emit({});
    return emit(expand({false, 0, bvh_.nodes()[0].bounds}), 1);
  }

  int depth() const { return depth_; }
  // (texel, component) of every reference to a quadtree root.
  const std::vector<std::pair<std::size_t, std::size_t>>& patchSlots() const { return patchSlots_; }

 private:
  std::vector<Candidate> expand(const Candidate& c) const {
    const scene::PatchBvh::Node& node = bvh_.nodes()[std::size_t(c.index)];
    std::vector<Candidate> children;
    if (node.leaf()) {
      for (int slot = node.next; slot < node.next + node.patchCount; ++slot)
        children.push_back({true, slot, patchBounds_[std::size_t(slot)]});
    } else {
      const int first = c.index + 1, second = node.next;
      children.push_back({false, first, bvh_.nodes()[std::size_t(first)].bounds});
      children.push_back({false, second, bvh_.nodes()[std::size_t(second)].bounds});
    }
    return children;
  }

  std::uint32_t emit(std::vector<Candidate> children, int depth = 1) {
    depth_ = std::max(depth_, depth);
    while (children.size() < 4) {
      int widest = -1;
      for (std::size_t i = 0; i < children.size(); ++i) {
        if (children[i].isPatch) continue;
        const scene::PatchBvh::Node& node = bvh_.nodes()[std::size_t(children[i].index)];
        const std::size_t grows = node.leaf() ? std::size_t(node.patchCount) : 2;
        if (children.size() - 1 + grows > 4) continue;
        if (widest < 0 || children[i].bounds.surfaceArea() > children[std::size_t(widest)].bounds.surfaceArea())
          widest = int(i);
      }
      if (widest < 0) break;
      std::vector<Candidate> grown = expand(children[std::size_t(widest)]);
      children.erase(children.begin() + widest);
      children.insert(children.end(), grown.begin(), grown.end());
    }
    const std::uint32_t index = appendNode(texels_);
    for (std::size_t slot = 0; slot < children.size(); ++slot) {
      const Candidate& c = children[slot];
      const std::uint32_t reference =
          c.isPatch ? std::uint32_t(c.index) * quadtreeNodes_ : emit(expand(c), depth + 1);
      writeChild(texels_, index, slot, c.bounds, reference, origin_, margin_);
      if (c.isPatch) patchSlots_.push_back({std::size_t(index) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES, slot});
    }
    return index;
  }

  const scene::PatchBvh& bvh_;
  const std::vector<scene::Aabb>& patchBounds_;
  glm::dvec3 origin_;
  double margin_;
  std::uint32_t quadtreeNodes_;
  std::vector<Texel>& texels_;
  int depth_ = 0;
  std::vector<std::pair<std::size_t, std::size_t>> patchSlots_;
};

struct ObjectRoot {
  std::uint32_t node;
  scene::Aabb bounds;
};

// Nodes over the objects' roots, four wide: the longest axis of their
// centres split into four runs, recursively (scenes hold a handful of
// objects, so nothing finer pays). Returns the root and the levels added.
std::uint32_t emitSceneNodes(std::vector<ObjectRoot> roots, std::vector<Texel>& texels, const glm::dvec3& origin,
                             double margin, int& depth) {
  scene::Aabb centres;
  for (const ObjectRoot& r : roots) centres.extend(r.bounds.centre());
  const glm::dvec3 extent = centres.hi - centres.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  std::sort(roots.begin(), roots.end(),
            [axis](const ObjectRoot& a, const ObjectRoot& b) { return a.bounds.centre()[axis] < b.bounds.centre()[axis]; });
  const std::uint32_t node = appendNode(texels);
  int deepest = 0;
  for (std::size_t slot = 0, begin = 0; slot < 4 && begin < roots.size(); ++slot) {
    const std::size_t end = begin + (roots.size() - begin + (3 - slot)) / (4 - slot);
    std::vector<ObjectRoot> run(roots.begin() + std::ptrdiff_t(begin), roots.begin() + std::ptrdiff_t(end));
    ObjectRoot child = run.front();
    if (run.size() > 1) {
      int below = 0;
      child.bounds = scene::Aabb();
      for (const ObjectRoot& r : run) child.bounds.extend(r.bounds);
      child.node = emitSceneNodes(std::move(run), texels, origin, margin, below);
      deepest = std::max(deepest, below);
    }
    writeChild(texels, node, slot, child.bounds, child.node, origin, margin);
    begin = end;
  }
  depth = deepest + 1;
  return node;
}

// Levels of a quadtree over k x k cells whose last level holds 2 x 2.
std::uint32_t quadtreeLevels(std::uint32_t rate) {
  std::uint32_t levels = 1;
  while ((1u << levels) < rate) ++levels;
  return levels;
}

// A texcoord patch as FACET_TEXCOORD_TEXELS texels (compute/layout/patch_records.h).
void packTexcoords(const scene::BezierPatch& patch, std::vector<glm::vec4>& texels) {
  static constexpr int kInteriorSlot[4] = {5, 6, 10, 9};
  std::array<glm::dvec3, 20> points;
  std::copy(patch.points.begin(), patch.points.end(), points.begin());
  for (int k = 0; k < 4; ++k) points[std::size_t(16 + k)] = patch.gregory ? patch.alternates[std::size_t(k)]
                                                                           : patch.points[std::size_t(kInteriorSlot[k])];
  for (std::size_t k = 0; k < points.size(); k += 2)
    texels.push_back(glm::vec4(float(points[k].x), float(points[k].y), float(points[k + 1].x), float(points[k + 1].y)));
}

}  // namespace

GpuScene packScene(const scene::Scene& scene, const scene::SceneGeometry& geometry, const glm::dvec3& origin,
                   double margin, bool tessellated) {
  GpuScene packed;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> patchSlots;
  std::vector<ObjectRoot> roots;
  int objectDepth = 0;
  std::uint32_t patchIds = 0, faceIds = 0;
  std::uint64_t quadtreeNodes = 0;
  for (std::size_t i = 0; i < geometry.objects.size(); ++i) {
    const scene::ObjectGeometry& object = geometry.objects[i];
    const scene::SubdivisionSurface& surface = object.surface;
    const scene::PatchBvh& bvh = object.bvh;
    const std::uint32_t rate = std::uint32_t(std::max(1, object.refinement.tessellationRate));
    const std::uint32_t levels = quadtreeLevels(rate);
    const std::uint32_t nodesPerPatch = ((1u << (2 * levels)) - 1) / 3;
    const std::uint64_t patchCount = bvh.leafPatches().size();

    std::vector<scene::Aabb> patchBounds;
    for (int source : bvh.leafPatches()) patchBounds.push_back(scene::patchBounds(surface.bezierPatch(source)));
    Collapse collapse(bvh, patchBounds, origin, margin, nodesPerPatch, packed.topNodes);
    layout::ObjectRange range{};
    roots.push_back({collapse.run(), bvh.nodes().empty() ? scene::Aabb() : bvh.nodes()[0].bounds});
    objectDepth = std::max(objectDepth, collapse.depth() + int(levels));
    patchSlots.push_back(collapse.patchSlots());

    range.firstPatch = std::uint32_t(packed.patches.size());
    range.patchCount = std::uint32_t(patchCount);
    range.patchIdOffset = patchIds;
    range.faceIdOffset = faceIds;
    range.material = std::uint32_t(scene.objects[i].material);
    range.rate = rate;
    range.quadtreeLevels = levels;
    range.firstQuadtreeNode = std::uint32_t(quadtreeNodes);  // relative to the quadtrees until all are placed
    range.quadtreeNodes = nodesPerPatch;
    range.firstBlock = std::uint32_t(packed.blocks);
    range.firstCell = std::uint32_t(packed.cells);
    range.firstGridVertex = std::uint32_t(packed.gridVertices);
    range.firstEdgeMidpoint = std::uint32_t(packed.edgeMidpoints);
    packed.objects.push_back(range);

    for (std::size_t slot = 0; slot < bvh.leafPatches().size(); ++slot) {
      const int source = bvh.leafPatches()[slot];
      const scene::PatchInfo& info = surface.patch(source);
      const scene::BezierPatch& bezier = surface.bezierPatch(source);
      layout::PatchRecord record{};
      record.kind = bezier.gregory ? layout::FACET_PATCH_GREGORY : layout::FACET_PATCH_BEZIER;
      record.firstPoint = std::uint32_t(packed.points.size());
      record.ptexFace = std::uint32_t(info.ptexFace);
      record.coarseFace = std::uint32_t(info.coarseFace);
      record.faceU0 = float(info.domain.u0);
      record.faceV0 = float(info.domain.v0);
      record.faceSize = float(info.domain.size);
      record.sourcePatch = std::uint32_t(source);
      record.boundaryMask = info.boundaryMask;
      record.depth = std::uint32_t(info.depth);
      record.pointCount = bezier.gregory ? layout::FACET_PATCH_POINTS_GREGORY : layout::FACET_PATCH_POINTS_BEZIER;
      record.transitionMask = info.transitionMask;
      record.firstNormal = layout::FACET_NO_NORMALS;
      if (const std::array<glm::dvec3, 4>* normals = surface.authoredNormals(source)) {
        record.firstNormal = std::uint32_t(packed.normals.size());
        for (const glm::dvec3& n : *normals) packed.normals.push_back(glm::vec4(glm::vec3(n), 0.0f));
      }
      record.firstTexcoord = layout::FACET_NO_TEXCOORDS;
      if (const scene::BezierPatch* texcoords = surface.texcoordPatch(source)) {
        record.firstTexcoord = std::uint32_t(packed.texcoords.size());
        packTexcoords(*texcoords, packed.texcoords);
      }
      auto add = [&](const glm::dvec3& p) { packed.points.push_back(glm::vec4(glm::vec3(p - origin), 0.0f)); };
      for (const glm::dvec3& p : bezier.points) add(p);
      if (bezier.gregory)
        for (const glm::dvec3& p : bezier.alternates) add(p);
      const std::uint64_t local = slot;
      packed.headers.push_back({record.firstPoint, record.kind, record.transitionMask, rate});
      packed.headers.push_back({std::uint32_t(packed.cells + local * rate * rate),
                                std::uint32_t(packed.gridVertices + local * (rate + 1) * (rate + 1)),
                                std::uint32_t(packed.edgeMidpoints + local * 4 * rate), std::uint32_t(i)});
      packed.patches.push_back(record);
    }
    const std::uint64_t blocksPerSide = std::uint64_t(1) << (levels - 1);
    packed.blocks += patchCount * blocksPerSide * blocksPerSide;
    packed.cells += patchCount * rate * rate;
    if (!tessellated) packed.cellBounds += patchCount * rate * rate * layout::FACET_CELL_TEXELS;
    if (tessellated) {
      packed.gridVertices += patchCount * (rate + 1) * (rate + 1);
      packed.edgeMidpoints += patchCount * 4 * rate;
    }
    quadtreeNodes += patchCount * nodesPerPatch;
    patchIds += std::uint32_t(surface.patchCount());
    faceIds += std::uint32_t(scene.objects[i].cage.faceCount());
  }
  int sceneDepth = 0;
  packed.rootNode = roots.size() == 1 ? roots[0].node
                                      : emitSceneNodes(roots, packed.topNodes, origin, margin, sceneDepth);
  if (std::uint32_t(sceneDepth + objectDepth) > layout::FACET_BVH4_MAX_DEPTH)
    throw gpu::Error("the scene's BVH is " + std::to_string(sceneDepth + objectDepth) +
                     " levels deep, more than the GPU traversal's " + std::to_string(layout::FACET_BVH4_MAX_DEPTH));
  const std::uint64_t topNodes = packed.topNodes.size() / layout::FACET_BVH4_TEXELS;
  packed.nodeCount = topNodes + quadtreeNodes;
  if (packed.nodeCount * 4 >= std::uint64_t(layout::FACET_BVH4_CELL))
    throw gpu::Error("the scene's micro-grid needs " + std::to_string(packed.nodeCount) +
                     " BVH nodes, more than the GPU ray caster addresses; lower the dicing rate (--tess-level)");
  for (std::size_t i = 0; i < packed.objects.size(); ++i) {
    layout::ObjectRange& range = packed.objects[i];
    range.firstQuadtreeNode += std::uint32_t(topNodes);
    for (const auto& [texel, component] : patchSlots[i]) packed.topNodes[texel][component] += range.firstQuadtreeNode;
  }
  // Post-order from the root: a node's top-level children come first.
  std::vector<std::pair<std::uint32_t, bool>> stack{{packed.rootNode, false}};
  while (!stack.empty()) {
    const auto [node, childrenDone] = stack.back();
    stack.pop_back();
    if (childrenDone) {
      packed.refitOrder.push_back(node);
      continue;
    }
    stack.push_back({node, true});
    for (std::uint32_t reference :
         packed.topNodes[std::size_t(node) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES])
      if (reference < topNodes) stack.push_back({reference, false});
  }
  return packed;
}

}  // namespace facet::gpu_backend
