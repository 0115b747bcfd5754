#include "engine/cpu/intersector.h"

namespace facet::cpu {

ExactIntersector::ExactIntersector(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                                   const ExactSettings& settings)
    : surface_(surface), bvh_(bvh), settings_(settings) {}

std::optional<SurfaceHit> ExactIntersector::closestHit(const Ray& ray) const {
  return intersectExact(surface_, bvh_, ray, settings_);
}

TessellatedIntersector::TessellatedIntersector(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                                               int rate)
    : surface_(surface), bvh_(bvh), tessellation_(TessellatedSurface::dice(surface, rate)) {}

std::optional<SurfaceHit> TessellatedIntersector::closestHit(const Ray& ray) const {
  return intersectTessellated(surface_, bvh_, tessellation_, ray);
}

}  // namespace facet::cpu
