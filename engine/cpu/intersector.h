#pragma once
// One object's ray caster for the reference renderer, its method chosen when
// the scene is built: after pbrt-v4's Primitive, with Intersect as closestHit
// and IntersectP as anyHit. Each refers to the object's surface and BVH, which
// must outlive it, and owns what its method adds to them. Its filter (empty:
// none) decides which hits count (intersect.h).

#include "engine/cpu/intersect.h"
#include "engine/cpu/ray.h"
#include "scenes/patch_bvh.h"
#include "scenes/scene.h"
#include "scenes/scene_geometry.h"
#include "scenes/subdivision_surface.h"

#include <cstddef>
#include <memory>
#include <optional>

namespace facet::cpu {

// Virtual rather than a variant: the renderer holds every method alike, and
// one indirect call per object and ray is nothing beside the BVH walk.
class Intersector {
 public:
  virtual ~Intersector() = default;

  // The nearest hit in [ray.tMin, ray.tMax).
  virtual std::optional<SurfaceHit> closestHit(const Ray& ray) const = 0;

  // Whether anything lies in [ray.tMin, ray.tMax) (shadow rays). The closest
  // hit's search gives the same answer as an early-out would: until it finds
  // its first hit it visits the same patches.
  bool anyHit(const Ray& ray) const { return closestHit(ray).has_value(); }
};

// The limit surface itself (intersectExact).
class ExactIntersector final : public Intersector {
 public:
  ExactIntersector(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                   const ExactSettings& settings = {}, HitFilter filter = {});

  std::optional<SurfaceHit> closestHit(const Ray& ray) const override;

 private:
  const scene::SubdivisionSurface& surface_;
  const scene::PatchBvh& bvh_;
  ExactSettings settings_;
  HitFilter filter_;
};

// The surface diced k x k per patch (intersectTessellated), once, on construction.
class TessellatedIntersector final : public Intersector {
 public:
  TessellatedIntersector(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh, int rate,
                         HitFilter filter = {});

  std::optional<SurfaceHit> closestHit(const Ray& ray) const override;

 private:
  const scene::SubdivisionSurface& surface_;
  const scene::PatchBvh& bvh_;
  TessellatedSurface tessellation_;
  HitFilter filter_;
};

// The intersector of the scene's object `index` (its geometry `object`) by
// the scene's method, with the filter of what its surface leaves out: a
// one-sided object's back faces (scene::cullsBackFaces), where its alpha
// lets a ray through (scene::hasCutout) and, with `crossings` (some
// material transmits), what a path's ray leaving a transmissive surface
// passes over (rules/surface/crossing.h). The scene must outlive it.
std::unique_ptr<Intersector> objectIntersector(const scene::Scene& scene, std::size_t index,
                                               const scene::ObjectGeometry& object, const ExactSettings& settings,
                                               bool crossings);

// Throws std::invalid_argument where the tessellated method's grids of every
// object would not fit in the memory a process lets itself use
// (scene::memoryLimit, docs/reliability.md "Limits"): checked before any
// object is diced.
void checkTessellationFitsInMemory(const scene::Scene& scene, const scene::SceneGeometry& geometry);

}  // namespace facet::cpu
