#include "engine/cpu/intersector.h"

#include <utility>

#include "rules/rules.h"
#include "scenes/texture.h"

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
  const bool culls = scene::cullsBackFaces(source, scene.materials[std::size_t(source.material)]);
  HitFilter filter;
  if (culls || scene::hasCutout(source))
    filter = [culls, index, &source, &surface = object.surface, &textures = scene.textures](const Ray& ray,
                                                                                            const SurfaceHit& hit) {
      if (culls && rules::f64::is_back_face(ray.direction, hit.geometricNormal)) return false;
      if (!scene::hasCutout(source)) return true;
      const glm::dvec2 uv = surface.evaluateTexcoord(hit.patch, hit.u, hit.v, source.alphaTexture.texCoord).uv;
      const double alpha = scene::sampleSlot(textures, source.alphaTexture, rules::f64::cutout_footprint(uv)).a;
      if (source.alphaMode == scene::AlphaMode::Blend)
        return rules::f64::blend_present(source.alphaFactor * alpha, ray.passThroughKey, std::uint32_t(index),
                                         std::uint32_t(hit.patch));
      return rules::f64::cutout_present(source.alphaFactor, alpha, source.alphaCutoff);
    };
  if (scene.render.method == scene::IntersectionMethod::Tessellated)
    return std::make_unique<TessellatedIntersector>(object.surface, object.bvh, object.refinement.tessellationRate,
                                                    std::move(filter));
  return std::make_unique<ExactIntersector>(object.surface, object.bvh, settings, std::move(filter));
}

}  // namespace facet::cpu
