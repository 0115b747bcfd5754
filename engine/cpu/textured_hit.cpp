#include "engine/cpu/textured_hit.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace facet::cpu {

namespace m = rules::f64;

m::TexturedSurface texturedHit(const scene::SubdivisionSurface& surface, const SurfaceHit& hit,
                               const std::vector<scene::Texture>& textures, const materials::MaterialTextures& t,
                               const m::BrdfParams& params, const glm::dvec3& n, const glm::dvec3& ng,
                               const glm::dvec3& direction, const glm::dvec3& emission, double coneSpread) {
  const scene::LimitPoint p = surface.evaluatePatch(hit.patch, hit.u, hit.v);
  // A slot reads the set of texture coordinates it names.
  const auto footprint = [&](const materials::TextureSlot& slot) {
    const scene::LimitTexcoord uv = surface.evaluateTexcoord(hit.patch, hit.u, hit.v, slot.texCoord);
    return m::TextureFootprint{uv.uv, uv.du, uv.dv, p.du, p.dv, hit.t * coneSpread, std::abs(glm::dot(ng, direction))};
  };
  const auto value = [&](const materials::TextureSlot& slot) {
    return scene::sampleSlot(textures, slot, footprint(slot));
  };
  // A vertex colour multiplies the base colour as its texture does (glTF COLOR_0).
  const glm::dvec3 base = glm::dvec3(value(t.baseColorTexture)) * surface.evaluateColor(hit.patch, hit.u, hit.v);
  const m::TexturedSurface textured = m::textured_surface(
      params, n, footprint(t.normalTexture), t.baseColor, t.metallic, t.roughness, t.normalScale, t.occlusionStrength,
      emission, base, glm::dvec3(value(t.metallicRoughnessTexture)), t.normalTexture.texture >= 0,
      glm::dvec3(value(t.normalTexture)), value(t.occlusionTexture).r, glm::dvec3(value(t.emissiveTexture)), t.unlit);
  return m::textured_layers(
      textured, footprint(t.clearcoatNormalTexture), value(t.clearcoatTexture).r, value(t.clearcoatRoughnessTexture).g,
      t.clearcoatNormalTexture.texture >= 0, glm::dvec3(value(t.clearcoatNormalTexture)), t.clearcoatNormalScale,
      glm::dvec3(value(t.sheenColorTexture)), t.anisotropyTexture.texture >= 0, glm::dvec3(value(t.anisotropyTexture)));
}

}  // namespace facet::cpu
