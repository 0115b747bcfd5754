#include "engine/cpu/intersector.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "rules/rules.h"
#include "scenes/memory_budget.h"
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
                                               const scene::ObjectGeometry& object, const ExactSettings& settings,
                                               bool crossings) {
  const scene::Object& source = scene.objects[index];
  const bool culls = scene::cullsBackFaces(source, scene.materials[std::size_t(source.material)]);
  HitFilter filter;
  if (culls || scene::hasCutout(source) || crossings)
    filter = [culls, crossings, index, &source, &surface = object.surface, &textures = scene.textures](
                 const Ray& ray, const SurfaceHit& hit) {
      if (crossings && rules::f64::crossing_passes_over(ray.crossing, ray.crossedObject == int(index), hit.t,
                                                        ray.direction, hit.geometricNormal))
        return false;
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

void checkTessellationFitsInMemory(const scene::Scene& scene, const scene::SceneGeometry& geometry) {
  if (scene.render.method != scene::IntersectionMethod::Tessellated) return;
  std::uint64_t needed = 0, patches = 0;
  int largestRate = 0;
  for (const scene::ObjectGeometry& object : geometry.objects) {
    const int rate = object.refinement.tessellationRate;
    needed += TessellatedSurface::bytes(std::uint64_t(object.surface.patchCount()), rate);
    patches += std::uint64_t(object.surface.patchCount());
    largestRate = std::max(largestRate, rate);
  }
  const scene::MemoryLimit limit = scene::memoryLimit();
  if (needed <= limit.bytes) return;
  const std::string rate = std::to_string(largestRate);
  throw std::invalid_argument(
      (scene.render.tessellationRate ? "render.tess_level (--tess-level) " + rate
                                     : "the dicing rate chosen for the image's size, up to " + rate) +
      ": the CPU reference's grids of " + std::to_string(patches) + " patches at " + rate + " x " + rate +
      " need about " + scene::gigabytes(needed) + " of memory and the limit is " + scene::gigabytes(limit.bytes) +
      " (" + limit.source + "); lower the dicing rate, or use the exact method (--method exact)");
}

}  // namespace facet::cpu
