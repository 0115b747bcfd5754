#include "engine/gpu_backend/gpu_scene.h"

#include "engine/gpu_backend/texture_data.h"

#include <algorithm>
#include <string>

#include "engine/gpu/gpu.h"
#include "engine/gpu_backend/top_levels.h"

namespace facet::gpu_backend {
namespace {

namespace layout = gpu_layout;

static_assert(layout::FACET_CHANNEL_TEXCOORD0 == 1u << int(scene::Channel::Texcoord0) &&
              layout::FACET_CHANNEL_TEXCOORD1 == 1u << int(scene::Channel::Texcoord1) &&
              layout::FACET_CHANNEL_COLOR == 1u << int(scene::Channel::Color));

// A cell reference holds node * 4 + slot below FACET_BVH4_CELL.
void checkNodeCount(std::uint64_t nodes) {
  if (nodes * 4 >= std::uint64_t(layout::FACET_BVH4_CELL))
    throw gpu::Error("the scene's micro-grid needs " + std::to_string(nodes) +
                     " BVH nodes, more than the GPU ray caster addresses; lower the dicing rate (--tess-level)");
}

// Levels of a quadtree over k x k cells whose last level holds 2 x 2.
std::uint32_t quadtreeLevels(std::uint32_t rate) {
  std::uint32_t levels = 1;
  while ((1u << levels) < rate) ++levels;
  return levels;
}

// A face-varying patch as texels (compute/layout/patch_records.h): a set of
// texture coordinates as FACET_TEXCOORD_TEXELS, two (u, v) points each;
// colours as FACET_COLOR_TEXELS, one RGB point each.
void packChannel(const scene::BezierPatch& patch, scene::Channel channel, std::vector<glm::vec4>& texels) {
  static constexpr int kInteriorSlot[4] = {5, 6, 10, 9};
  std::array<glm::dvec3, 20> points;
  std::copy(patch.points.begin(), patch.points.end(), points.begin());
  for (int k = 0; k < 4; ++k)
    points[std::size_t(16 + k)] =
        patch.gregory ? patch.alternates[std::size_t(k)] : patch.points[std::size_t(kInteriorSlot[k])];
  if (channel == scene::Channel::Color) {
    for (const glm::dvec3& p : points) texels.push_back(glm::vec4(glm::vec3(p), 0.0f));
    return;
  }
  for (std::size_t k = 0; k < points.size(); k += 2)
    texels.push_back(glm::vec4(float(points[k].x), float(points[k].y), float(points[k + 1].x), float(points[k + 1].y)));
}

// Each object's entry in the top levels: its BVH, its patches' bounds in
// leaf order and the quadtree below each patch.
std::vector<TopLevelObject> topLevelObjects(const scene::SceneGeometry& geometry) {
  std::vector<TopLevelObject> tops;
  std::uint64_t quadtreeNodes = 0;
  for (const scene::ObjectGeometry& object : geometry.objects) {
    TopLevelObject top;
    top.bvh = &object.bvh;
    top.quadtreeLevels = quadtreeLevels(std::uint32_t(std::max(1, object.refinement.tessellationRate)));
    top.nodesPerPatch = ((1u << (2 * top.quadtreeLevels)) - 1) / 3;
    quadtreeNodes += object.bvh.leafPatches().size() * top.nodesPerPatch;
    tops.push_back(std::move(top));
  }
  // Checked before the top levels are built: their depth fits the
  // traversal's stack whenever the nodes are addressable (top_levels.h).
  checkNodeCount(quadtreeNodes + geometry.objects.size());
  for (std::size_t i = 0; i < tops.size(); ++i)
    for (int source : tops[i].bvh->leafPatches())
      tops[i].patchBounds.push_back(scene::patchBounds(geometry.objects[i].surface.bezierPatch(source)));
  return tops;
}

// The patch in leaf slot `slot` of object `object` (its range as far as
// set): its record, authored normals, face-varying texels, control points
// and two header texels, whose cells, grid vertices and edge midpoints start
// at the object's.
void packPatch(GpuScene& packed, const scene::SubdivisionSurface& surface, int source, std::uint64_t slot,
               const layout::ObjectRange& range, std::uint32_t object, const glm::dvec3& origin) {
  const scene::PatchInfo& info = surface.patch(source);
  const scene::BezierPatch& bezier = surface.bezierPatch(source);
  layout::PatchRecord record{};
  record.sourcePatch = std::uint32_t(source);
  record.coarseFace = std::uint32_t(info.coarseFace);
  record.faceU0 = float(info.domain.u0);
  record.faceV0 = float(info.domain.v0);
  record.faceSize = float(info.domain.size);
  record.ptexFace = std::uint32_t(info.ptexFace);
  record.firstNormal = layout::FACET_NO_NORMALS;
  if (const std::array<glm::dvec3, 4>* normals = surface.authoredNormals(source)) {
    record.firstNormal = std::uint32_t(packed.normals.size());
    for (const glm::dvec3& n : *normals) packed.normals.push_back(glm::vec4(glm::vec3(n), 0.0f));
    if (const std::array<glm::dvec4, 4>* tangents = surface.authoredTangents(source))
      for (const glm::dvec4& t : *tangents) packed.normals.push_back(glm::vec4(t));
  }
  record.firstTexcoord = range.channels ? std::uint32_t(packed.texcoords.size()) : layout::FACET_NO_TEXCOORDS;
  for (int c = 0; c < scene::kChannelCount; ++c)
    if (const scene::BezierPatch* values = surface.channelPatch(scene::Channel(c), source))
      packChannel(*values, scene::Channel(c), packed.texcoords);
  const std::uint32_t firstPoint = std::uint32_t(packed.points.size());
  // The first point relative to the eye, the others relative to it
  // (compute/layout/patch_records.h), each difference taken in double. The
  // anchor's rounding moves the whole patch by less than an ulp and leaves
  // its shape: taken from the rounded anchor, the other points would keep
  // their own rounding while the first took the anchor's, and the normal at
  // that corner would turn by the ratio of the two to the patch's size.
  const glm::dvec3 anchor = bezier.points[0];
  packed.points.push_back(glm::vec4(glm::vec3(anchor - origin), 0.0f));
  auto add = [&](const glm::dvec3& p) { packed.points.push_back(glm::vec4(glm::vec3(p - anchor), 0.0f)); };
  for (std::size_t k = 1; k < bezier.points.size(); ++k) add(bezier.points[k]);
  if (bezier.gregory)
    for (const glm::dvec3& p : bezier.alternates) add(p);
  packed.headers.push_back({firstPoint, bezier.gregory ? layout::FACET_PATCH_GREGORY : layout::FACET_PATCH_BEZIER,
                            info.transitionMask, range.rate});
  packed.headers.push_back({std::uint32_t(packed.cells + slot * range.rate * range.rate),
                            std::uint32_t(packed.gridVertices + slot * (range.rate + 1) * (range.rate + 1)),
                            std::uint32_t(packed.edgeMidpoints + slot * 4 * range.rate), object});
  packed.patches.push_back(record);
}

// Moves every object's quadtrees after the top-level nodes and points the
// top levels' references to quadtree roots at them.
void placeQuadtrees(GpuScene& packed, const TopLevels& top, std::uint64_t topNodes) {
  for (std::size_t i = 0; i < packed.objects.size(); ++i) {
    layout::ObjectRange& range = packed.objects[i];
    range.firstQuadtreeNode += std::uint32_t(topNodes);
    for (const auto& [texel, component] : top.patchSlots[i])
      packed.topNodes[texel][component] += range.firstQuadtreeNode;
  }
}

// Post-order from the root: a node's top-level children come first.
std::vector<std::uint32_t> refitOrder(const GpuScene& packed, std::uint64_t topNodes) {
  std::vector<std::uint32_t> order;
  std::vector<std::pair<std::uint32_t, bool>> stack{{packed.rootNode, false}};
  while (!stack.empty()) {
    const auto [node, childrenDone] = stack.back();
    stack.pop_back();
    if (childrenDone) {
      order.push_back(node);
      continue;
    }
    stack.push_back({node, true});
    for (std::uint32_t reference :
         packed.topNodes[std::size_t(node) * layout::FACET_BVH4_TEXELS + layout::FACET_BVH4_REFERENCES])
      if (reference < topNodes) stack.push_back({reference, false});
  }
  return order;
}

}  // namespace

GpuScene packScene(const scene::Scene& scene, const scene::SceneGeometry& geometry, const glm::dvec3& origin,
                   double margin, bool tessellated) {
  GpuScene packed;
  const std::vector<TopLevelObject> tops = topLevelObjects(geometry);
  const TopLevels top = buildTopLevels(tops, origin, margin, packed.topNodes);
  packed.rootNode = top.root;
  packed.depth = top.depth;

  std::uint32_t patchIds = 0, faceIds = 0;
  std::uint64_t quadtreeNodes = 0;
  for (std::size_t i = 0; i < geometry.objects.size(); ++i) {
    const scene::ObjectGeometry& object = geometry.objects[i];
    const scene::SubdivisionSurface& surface = object.surface;
    const scene::PatchBvh& bvh = object.bvh;
    const std::uint32_t rate = std::uint32_t(std::max(1, object.refinement.tessellationRate));
    const std::uint32_t levels = tops[i].quadtreeLevels;
    const std::uint32_t nodesPerPatch = tops[i].nodesPerPatch;
    const std::uint64_t patchCount = bvh.leafPatches().size();
    layout::ObjectRange range{};
    range.firstPatch = std::uint32_t(packed.patches.size());
    range.patchCount = std::uint32_t(patchCount);
    range.patchIdOffset = patchIds;
    range.faceIdOffset = faceIds;
    range.rate = rate;
    range.quadtreeLevels = levels;
    range.firstQuadtreeNode = std::uint32_t(quadtreeNodes);  // relative to the quadtrees until all are placed
    range.quadtreeNodes = nodesPerPatch;
    range.firstBlock = std::uint32_t(packed.blocks);
    range.firstCell = std::uint32_t(packed.cells);
    range.firstGridVertex = std::uint32_t(packed.gridVertices);
    range.firstEdgeMidpoint = std::uint32_t(packed.edgeMidpoints);
    range.channels = 0;
    for (int c = 0; c < scene::kChannelCount; ++c)
      if (surface.hasChannel(scene::Channel(c))) range.channels |= 1u << c;
    setObjectShading(range, scene, geometry, i);
    packed.objects.push_back(range);

    for (std::size_t slot = 0; slot < bvh.leafPatches().size(); ++slot)
      packPatch(packed, surface, bvh.leafPatches()[slot], slot, range, std::uint32_t(i), origin);
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
  const std::uint64_t topNodes = packed.topNodes.size() / layout::FACET_BVH4_TEXELS;
  packed.nodeCount = topNodes + quadtreeNodes;
  checkNodeCount(packed.nodeCount);
  placeQuadtrees(packed, top, topNodes);
  packed.refitOrder = refitOrder(packed, topNodes);
  return packed;
}

void setObjectShading(layout::ObjectRange& range, const scene::Scene& scene, const scene::SceneGeometry& geometry,
                      std::size_t index) {
  const scene::Object& sceneObject = scene.objects[index];
  const bool cutout = scene::hasCutout(sceneObject);
  range.material = std::uint32_t(sceneObject.material);
  range.flags = (scene::cullsBackFaces(sceneObject, scene.materials[std::size_t(sceneObject.material)])
                     ? layout::FACET_OBJECT_CULL_BACK_FACES
                     : 0u) |
                (sceneObject.shadowCatcher ? layout::FACET_OBJECT_SHADOW_CATCHER : 0u) |
                (sceneObject.holdout ? layout::FACET_OBJECT_HOLDOUT : 0u) |
                (scene::sealsInside(sceneObject, geometry.objects[index]) ? layout::FACET_OBJECT_SEALED : 0u) |
                (cutout ? layout::FACET_OBJECT_CUTOUT : 0u) |
                (sceneObject.alphaMode == scene::AlphaMode::Blend ? layout::FACET_OBJECT_BLEND : 0u) |
                (geometry.objects[index].surface.hasAuthoredTangents() ? layout::FACET_OBJECT_TANGENTS : 0u);
  // Without a cut-out its fields are zero, whatever the range held before.
  const layout::TextureSlotRecord slot =
      cutout ? textureSlotRecord(sceneObject.alphaTexture) : layout::TextureSlotRecord{};
  range.alphaCutoff = sceneObject.alphaMode == scene::AlphaMode::Mask ? float(sceneObject.alphaCutoff) : 0.0f;
  range.alphaFactor = cutout ? float(sceneObject.alphaFactor) : 0.0f;
  range.alphaTexture = slot.texture;
  range.alphaOffsetX = slot.offsetX, range.alphaOffsetY = slot.offsetY;
  range.alphaCosRotation = slot.cosRotation, range.alphaSinRotation = slot.sinRotation;
  range.alphaScaleX = slot.scaleX, range.alphaScaleY = slot.scaleY;
  range.alphaTexCoord = slot.texCoord;
}

}  // namespace facet::gpu_backend
