#include "engine/cpu/textured_hit.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace facet::cpu {

namespace m = rules::f64;

m::MaterialTexels materialTexels(const scene::SubdivisionSurface& surface, const SurfaceHit& hit,
                                 const std::vector<scene::Texture>& textures, const materials::MaterialTextures& t,
                                 const glm::dvec3& ng, const glm::dvec3& direction, double coneSpread) {
  const scene::LimitPoint p = surface.evaluatePatch(hit.patch, hit.u, hit.v);
  // A slot reads the set of texture coordinates it names.
  const auto footprint = [&](const materials::TextureSlot& slot) {
    const scene::LimitTexcoord uv = surface.evaluateTexcoord(hit.patch, hit.u, hit.v, slot.texCoord);
    return m::TextureFootprint{uv.uv, uv.du, uv.dv, p.du, p.dv, hit.t * coneSpread, std::abs(glm::dot(ng, direction))};
  };
  const auto uvMap = [](const materials::TextureSlot& slot) {
    return m::slot_uv_map(std::cos(slot.rotation), std::sin(slot.rotation), slot.scale);
  };
  const auto value = [&](const materials::TextureSlot& slot) {
    return scene::sampleSlot(textures, slot, footprint(slot));
  };
  m::MaterialTexels texels{};
  texels.base = glm::dvec3(value(t.baseColorTexture)) * surface.evaluateColor(hit.patch, hit.u, hit.v);
  texels.metallic_roughness = glm::dvec3(value(t.metallicRoughnessTexture));
  texels.normal = glm::dvec3(value(t.normalTexture));
  texels.normal_frame = footprint(t.normalTexture);
  texels.normal_map = uvMap(t.normalTexture);
  texels.occlusion = value(t.occlusionTexture).r;
  texels.emission = glm::dvec3(value(t.emissiveTexture));
  texels.coat = value(t.clearcoatTexture).r;
  texels.coat_roughness = value(t.clearcoatRoughnessTexture).g;
  texels.coat_normal = glm::dvec3(value(t.clearcoatNormalTexture));
  texels.coat_normal_frame = footprint(t.clearcoatNormalTexture);
  texels.coat_normal_map = uvMap(t.clearcoatNormalTexture);
  texels.sheen = glm::dvec3(value(t.sheenColorTexture));
  texels.anisotropy = glm::dvec3(value(t.anisotropyTexture));
  texels.transmission = value(t.transmissionTexture).r;
  texels.specular_color = glm::dvec3(value(t.specularColorTexture));
  texels.specular = value(t.specularTexture).a;
  if (t.sheenRoughnessTexture.texture >= 0) {
    texels.sheen_alpha = m::textured_sheen_alpha(t.sheenRoughness, value(t.sheenRoughnessTexture).a);
    const m::SheenRows at = m::sheen_rows_at(texels.sheen_alpha);
    const std::vector<glm::dvec4>& rows = materials::sheenAlbedoRows();
    const std::size_t first = 2 * std::size_t(at.first);
    texels.sheen_albedo_near = glm::mix(rows[first], rows[first + 2], at.weight);
    texels.sheen_albedo_far = glm::mix(rows[first + 1], rows[first + 3], at.weight);
  }
  texels.iridescence = value(t.iridescenceTexture).r;
  texels.iridescence_thickness = value(t.iridescenceThicknessTexture).g;
  return texels;
}

m::TexturedFactors texturedFactors(const materials::MaterialTextures& t) {
  m::TexturedFactors f;
  f.base = t.baseColor;
  f.metallic = t.metallic;
  f.roughness = t.roughness;
  f.normal_mapped = t.normalTexture.texture >= 0;
  f.normal_scale = t.normalScale;
  f.occlusion_strength = t.occlusionStrength;
  f.unlit = t.unlit;
  f.coat_normal_mapped = t.clearcoatNormalTexture.texture >= 0;
  f.coat_normal_scale = t.clearcoatNormalScale;
  f.anisotropy_mapped = t.anisotropyTexture.texture >= 0;
  f.specular_color = t.specularColor;
  f.specular = t.specular;
  f.film_thickness_mapped = t.iridescenceThicknessTexture.texture >= 0;
  f.film_thickness_minimum = t.iridescenceThicknessMinimum;
  f.sheen_roughness_mapped = t.sheenRoughnessTexture.texture >= 0;
  return f;
}

}  // namespace facet::cpu
