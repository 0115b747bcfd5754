#include "engine/gpu_backend/shading_records.h"

#include <glm/trigonometric.hpp>

#include <bit>
#include <cmath>
#include <optional>

#include "engine/gpu_backend/texture_data.h"
#include "materials/material.h"

namespace facet::gpu_backend {

namespace layout = gpu_layout;

namespace {

// Appends the tables' entries as (scale, bias, 0, 0) texels; returns their
// common size (0 for none).
std::uint32_t appendDfgTables(const std::vector<ibl::DfgTable>& tables, std::vector<glm::vec4>& texels) {
  for (const ibl::DfgTable& table : tables)
    for (std::size_t i = 0; i + 1 < table.scaleBias.size(); i += 2)
      texels.emplace_back(table.scaleBias[i], table.scaleBias[i + 1], 0.0f, 0.0f);
  return tables.empty() ? 0 : std::uint32_t(tables.front().size);
}

}  // namespace

std::vector<layout::MaterialRecord> materialRecords(const scene::Scene& scene,
                                                    const ibl::EnvironmentLighting* environment,
                                                    const ibl::CompensationTables& compensation) {
  std::vector<layout::MaterialRecord> records;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const rules::f32::BrdfParams p = materials::toParams32(scene.materials[i]);
    const bool prefiltered = environment && !environment->dfgTable.empty();
    layout::MaterialRecord r{p.d_model,
                             p.g_model,
                             p.f_model,
                             p.alpha,
                             p.f0.x,
                             p.f0.y,
                             p.f0.z,
                             p.eta.x,
                             p.eta.y,
                             p.eta.z,
                             p.k.x,
                             p.k.y,
                             p.k.z,
                             p.diffuse.x,
                             p.diffuse.y,
                             p.diffuse.z,
                             prefiltered ? std::uint32_t(environment->dfgTable[i]) : 0u};
    const materials::TextureSlot none;
    const glm::vec3 emission(scene.materials[i].emission);
    r.emissionR = emission.r, r.emissionG = emission.g, r.emissionB = emission.b;
    const std::optional<materials::MaterialTextures>& t = scene.materials[i].textures;
    r.textured = t ? 1u : 0u;
    r.unlit = t && t->unlit ? 1u : 0u;
    if (t) {
      r.baseR = float(t->baseColor.r), r.baseG = float(t->baseColor.g), r.baseB = float(t->baseColor.b);
      r.metallic = float(t->metallic);
      r.roughness = float(t->roughness);
      r.normalScale = float(t->normalScale);
      r.occlusionStrength = float(t->occlusionStrength);
      r.specularR = float(t->specularColor.r), r.specularG = float(t->specularColor.g);
      r.specularB = float(t->specularColor.b);
      r.specular = float(t->specular);
    }
    r.baseColorTexture = textureSlotRecord(t ? t->baseColorTexture : none);
    r.metallicRoughnessTexture = textureSlotRecord(t ? t->metallicRoughnessTexture : none);
    r.normalTexture = textureSlotRecord(t ? t->normalTexture : none);
    r.occlusionTexture = textureSlotRecord(t ? t->occlusionTexture : none);
    r.emissiveTexture = textureSlotRecord(t ? t->emissiveTexture : none);
    r.clearcoatTexture = textureSlotRecord(t ? t->clearcoatTexture : none);
    r.clearcoatRoughnessTexture = textureSlotRecord(t ? t->clearcoatRoughnessTexture : none);
    r.clearcoatNormalTexture = textureSlotRecord(t ? t->clearcoatNormalTexture : none);
    r.clearcoatNormalScale = t ? float(t->clearcoatNormalScale) : 1.0f;
    r.sheenColorTexture = textureSlotRecord(t ? t->sheenColorTexture : none);
    r.anisotropyTexture = textureSlotRecord(t ? t->anisotropyTexture : none);
    r.transmissionTexture = textureSlotRecord(t ? t->transmissionTexture : none);
    r.specularTexture = textureSlotRecord(t ? t->specularTexture : none);
    r.specularColorTexture = textureSlotRecord(t ? t->specularColorTexture : none);
    r.iridescenceTexture = textureSlotRecord(t ? t->iridescenceTexture : none);
    r.iridescenceThicknessTexture = textureSlotRecord(t ? t->iridescenceThicknessTexture : none);
    r.iridescenceThicknessMinimum = t ? float(t->iridescenceThicknessMinimum) : 0.0f;
    r.sheenRoughnessTexture = textureSlotRecord(t ? t->sheenRoughnessTexture : none);
    r.sheenRoughnessFactor = t ? float(t->sheenRoughness) : 0.0f;
    const int table = compensation.tableOfMaterial[i];
    r.compensationTable =
        table == ibl::CompensationTables::kNone ? layout::FACET_NO_COMPENSATION : std::uint32_t(table);
    if (materials::isTransmissive(scene.materials[i])) {
      // From the CPU reference's double parameters, so that both read one sigma.
      const rules::f64::TransmissionParams transmission = materials::transmissionParams64(scene.materials[i]);
      r.transmissive = 1u;
      r.transmission = float(transmission.transmission);
      r.ior = float(transmission.ior);
      r.thinWalled = transmission.thin_walled ? 1u : 0u;
      r.sigmaR = float(transmission.sigma.x), r.sigmaG = float(transmission.sigma.y);
      r.sigmaB = float(transmission.sigma.z);
      r.thickness = float(transmission.thickness);
    }
    r.anisotropy = p.anisotropy;
    r.anisotropyCos = float(std::cos(scene.materials[i].anisotropyRotation));
    r.anisotropySin = float(std::sin(scene.materials[i].anisotropyRotation));
    r.clearcoat = p.clearcoat;
    r.clearcoatAlpha = p.clearcoat_alpha;
    r.coatDfgTable = prefiltered && environment->coatDfgTable >= 0 ? std::uint32_t(environment->coatDfgTable) : 0u;
    r.sheenR = p.sheen_color.x, r.sheenG = p.sheen_color.y, r.sheenB = p.sheen_color.z;
    r.sheenAlpha = p.sheen_alpha;
    r.sheenAlbedo0 = p.sheen_albedo_near.x, r.sheenAlbedo1 = p.sheen_albedo_near.y;
    r.sheenAlbedo2 = p.sheen_albedo_near.z, r.sheenAlbedo3 = p.sheen_albedo_near.w;
    r.sheenAlbedo4 = p.sheen_albedo_far.x, r.sheenAlbedo5 = p.sheen_albedo_far.y;
    r.sheenAlbedo6 = p.sheen_albedo_far.z, r.sheenAlbedo7 = p.sheen_albedo_far.w;
    r.iridescence = p.iridescence, r.iridescenceIor = p.iridescence_ior;
    r.iridescenceThickness = p.iridescence_thickness;
    records.push_back(r);
  }
  return records;
}

EnvironmentData environmentData(const ibl::EnvironmentLighting& lighting, layout::FrameParams& frame) {
  const scene::Environment& environment = *lighting.environment;
  const scene::EnvironmentMap& map = *environment.map;
  EnvironmentData data;
  auto appendRgb = [](std::vector<glm::vec4>& to, const std::vector<float>& rgb) {
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) to.emplace_back(rgb[i], rgb[i + 1], rgb[i + 2], 0.0f);
  };
  appendRgb(data.texels, map.rgb);
  // Filtered with the environment technique: the density's chain in w.
  const bool densityChain = !lighting.pdfChain.empty();
  if (densityChain)
    for (std::size_t i = 0; i < data.texels.size(); ++i) data.texels[i].w = float(lighting.pdfChain[0].rgb[3 * i]);
  frame.environmentIntensity = float(environment.intensity);
  frame.environmentCosRotation = float(lighting.cosRotation);
  frame.environmentSinRotation = float(lighting.sinRotation);
  frame.environmentSamples = std::uint32_t(environment.samples);
  frame.environmentSeed = environment.seed;
  frame.environmentWidth = std::uint32_t(map.width);
  frame.environmentHeight = std::uint32_t(map.height);
  const ibl::EnvironmentDistribution& d = lighting.distribution;
  for (std::size_t i = 0; i < d.keep.size(); ++i)
    data.sampling.push_back({std::bit_cast<std::uint32_t>(float(d.keep[i])),
                             std::bit_cast<std::uint32_t>(float(d.texelPdf[i])), d.alias[i], 0});
  std::vector<glm::vec4>& t = data.tables;
  auto offset = [&] { return std::uint32_t(t.size()); };
  // Levels 1.. of the chain or the ladder; level 0 is read from the texels.
  auto appendLevels = [&](const auto& levels) {
    data.levels.push_back({0, std::uint32_t(map.width), std::uint32_t(map.height), 0});
    for (std::size_t i = 1; i < levels.size(); ++i) {
      data.levels.push_back({offset(), std::uint32_t(levels[i].width), std::uint32_t(levels[i].height), 0});
      for (std::size_t j = 0; j + 2 < levels[i].rgb.size(); j += 3)
        t.emplace_back(float(levels[i].rgb[j]), float(levels[i].rgb[j + 1]), float(levels[i].rgb[j + 2]),
                       densityChain ? float(lighting.pdfChain[i].rgb[j]) : 0.0f);
    }
    frame.levelCount = std::uint32_t(levels.size());
  };
  if (environment.method == scene::IblMethod::Filtered) appendLevels(lighting.mipChain);
  if (environment.method != scene::IblMethod::Prefiltered) return data;
  const ibl::PrefilteredEnvironment& p = lighting.prefiltered;
  appendLevels(p.levels);
  frame.shOffset = offset();
  for (const glm::vec4& texel : ibl::irradianceTable(p)) t.push_back(texel);
  frame.dfgOffset = offset();
  frame.dfgSize = appendDfgTables(p.dfg, t);
  return data;
}

std::vector<glm::vec4> compensationTexels(const ibl::CompensationTables& compensation, layout::FrameParams& frame) {
  std::vector<glm::vec4> texels;
  frame.compensationSize = appendDfgTables(compensation.tables, texels);
  return texels;
}

std::vector<glm::vec4> sheenAlbedoRowTexels(const scene::Scene& scene) {
  for (const materials::Material& m : scene.materials)
    if (m.textures && m.textures->sheenRoughnessTexture.texture >= 0) {
      const std::vector<glm::dvec4>& rows = materials::sheenAlbedoRows();
      return std::vector<glm::vec4>(rows.begin(), rows.end());
    }
  return {};
}

std::uint32_t environmentSlots(const ibl::EnvironmentLighting* lighting) {
  if (!lighting) return 0;
  const scene::Environment& e = *lighting->environment;
  if (!e.occlusion || e.method == scene::IblMethod::Prefiltered) return 1;
  const bool environmentSamples = e.method == scene::IblMethod::Sampled || lighting->environmentSamples;
  return (environmentSamples ? 2 : 1) * std::uint32_t(e.samples);
}

std::vector<layout::LightRecord> lightRecords(const scene::Scene& scene, const glm::dvec3& origin) {
  std::vector<layout::LightRecord> records;
  for (const scene::Light& light : scene.lights) {
    layout::LightRecord r{};
    r.type = light.type == scene::LightType::Directional ? layout::FACET_LIGHT_DIRECTIONAL
             : light.type == scene::LightType::Point     ? layout::FACET_LIGHT_POINT
                                                         : layout::FACET_LIGHT_SPOT;
    r.colorR = float(light.color.r), r.colorG = float(light.color.g), r.colorB = float(light.color.b);
    const glm::vec3 position(light.position - origin);
    r.positionX = position.x, r.positionY = position.y, r.positionZ = position.z;
    r.directionX = float(light.direction.x), r.directionY = float(light.direction.y),
    r.directionZ = float(light.direction.z);
    r.cosOuter = float(std::cos(glm::radians(light.outerConeDegrees)));
    r.cosInner = float(std::cos(glm::radians(light.innerConeDegrees)));
    records.push_back(r);
  }
  return records;
}

}  // namespace facet::gpu_backend
