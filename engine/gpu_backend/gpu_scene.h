// A scene's geometry packed for the GPU ray caster: the top levels of each
// object's 4-wide BVH (its patch BVH collapsed), patch records, headers and
// control points, and where each object's micro-grid and quadtrees go
// (compute/layout/wide_bvh.h, raycast_layout.h).
//
// Everything is rebased on `origin` (the eye) in double before it is
// rounded to float, so the kernels' error scales with the scene's size seen
// from the camera, not with its distance from the world origin.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "engine/gpu_backend/raycast_layout.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"

namespace facet::gpu_backend {

struct GpuScene {
  std::vector<Texel> topNodes;  // nodes 0 .. topNodes.size() / FACET_BVH4_TEXELS - 1 of the node buffer
  std::uint32_t rootNode = 0;
  int depth = 0;  // the longest path of nodes from the root to a cell (top_levels.h)
  // The top nodes, children before parents: the order in which their boxes
  // are refitted to the diced cells (compute/raycast/dicing/refit_top_levels.comp).
  std::vector<std::uint32_t> refitOrder;
  std::uint64_t nodeCount = 0;  // top levels and every quadtree
  std::vector<gpu_layout::PatchRecord> patches;
  std::vector<Texel> headers;  // FACET_HEADER_TEXELS per patch
  std::vector<glm::vec4> points;
  std::vector<glm::vec4> normals;    // authored, 4 per patch that has them, then its 4 tangents where it has those
  std::vector<glm::vec4> texcoords;  // per patch, the face-varying channels of its cage (patch_records.h)
  std::vector<gpu_layout::ObjectRange> objects;
  std::uint64_t blocks = 0;         // 2 x 2 cell blocks, one dicing invocation each
  std::uint64_t gridVertices = 0;   // tessellated only
  std::uint64_t edgeMidpoints = 0;  // tessellated only
  std::uint64_t cells = 0;
  std::uint64_t cellBounds = 0;  // exact only: texels
};

// `margin` grows every top-level box (the exact method's root tolerance).
GpuScene packScene(const scene::Scene& scene, const scene::SceneGeometry& geometry, const glm::dvec3& origin,
                   double margin, bool tessellated);

// The fields of object `index`'s range that its scene object and material
// decide (its material, its flags and cut-out), as packScene sets them:
// ranges whose geometry is packed already take another scene's materials.
void setObjectShading(gpu_layout::ObjectRange& range, const scene::Scene& scene, const scene::SceneGeometry& geometry,
                      std::size_t index);

}  // namespace facet::gpu_backend
