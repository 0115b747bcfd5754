#include "engine/cpu/intersector.h"

#include <utility>

#include "rules/rules.h"

namespace facet::cpu {

ExactIntersector::ExactIntersector(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                                   const ExactSettings& settings, HitFilter filter)
    : surface_(surface), bvh_(bvh), settings_(settings), filter_(std::move(filter)) {}

std::optional<SurfaceHit> ExactIntersector::closestHit(const Ray& ray) const {
  return intersectExact(surface_, bvh_, ray, settings_, filter_);
}

TessellatedIntersector::TessellatedIntersector(const scene::SubdivisionSurface& surface, const scene::PatchBvh& bvh,
                                               int rate, HitFilter filter)
    : surface_(surface),
      bvh_(bvh),
      tessellation_(TessellatedSurface::dice(surface, rate)),
      filter_(std::move(filter)) {}

std::optional<SurfaceHit> TessellatedIntersector::closestHit(const Ray& ray) const {
  return intersectTessellated(surface_, bvh_, tessellation_, ray, filter_);
}

std::unique_ptr<Intersector> objectIntersector(const scene::Scene& scene, std::size_t index,
                                               const scene::ObjectGeometry& object, const ExactSettings& settings) {
  const scene::Object& source = scene.objects[index];
  HitFilter filter;
  if (scene::cullsBackFaces(source, scene.materials[std::size_t(source.material)]))
    filter = [](const Ray& ray, const SurfaceHit& hit) {
      return !rules::f64::is_back_face(ray.direction, hit.geometricNormal);
    };
  if (scene.render.method == scene::IntersectionMethod::Tessellated)
    return std::make_unique<TessellatedIntersector>(object.surface, object.bvh, object.refinement.tessellationRate,
                                                    std::move(filter));
  return std::make_unique<ExactIntersector>(object.surface, object.bvh, settings, std::move(filter));
}

}  // namespace facet::cpu
